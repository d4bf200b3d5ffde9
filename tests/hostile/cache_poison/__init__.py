"""At import, tries to rewrite the grader's reference cache: every entry, and new ones.  A poisoned entry would
make the reference itself lose points.  The cache attacked is the one the grader uses in the test (target.txt
names it, as a student could guess it); the attack leaves every other folder alone, so that a failing test
cannot harm a real cache."""
import json
import os

with open(os.path.join(os.path.dirname(__file__), "target.txt")) as _handle:
    _root = json.load(_handle)["cache"]

writes = 0
for _dirpath, _dirnames, _filenames in os.walk(_root):
    for _name in _filenames:
        try:
            with open(os.path.join(_dirpath, _name), "w") as _handle:
                _handle.write('{"poisoned": true}')
            writes += 1
        except OSError:
            pass
    try:
        with open(os.path.join(_dirpath, "poison.json"), "w") as _handle:
            _handle.write("{}")
        writes += 1
    except OSError:
        pass
try:  # into the cache itself (makedirs would count a fresh tree in the child's own private /tmp)
    os.mkdir(os.path.join(_root, "poison"))
    writes += 1
except OSError:
    pass
print("cache writes:", writes)
