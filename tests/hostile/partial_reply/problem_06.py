"""Answers frames() with a reply header announcing 1000 bytes, sends ten of them, and waits forever: a blocking
read of the rest used to wait with it."""
import os
import struct
import sys
import time


def frames():
    fd = int(sys.argv[2])
    os.write(fd, struct.pack(">I", 1000) + b'{"id": 2, ')
    while True:
        time.sleep(1)


def vectors():
    return frames()
