"""Prints tens of megabytes at import."""
line = "spam " * 40
for _ in range(200_000):
    print(line)
