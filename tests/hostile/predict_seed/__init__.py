"""Predicts the seed of its own random inputs and prints it: the content hash of the student's files (its package
but the template's README.md, names and contents, as the loader hashes them), hashed once more as a batch derived
its students' seeds from their files alone.  A seed a submission can compute is inputs it can prepare for."""
import hashlib
import os

_HERE = os.path.dirname(os.path.abspath(__file__))
_KEPT = (".py", ".toml", ".ipynb", ".md", ".txt")
_digest = hashlib.sha256()
for _name in sorted(os.listdir(_HERE)):
    _path = os.path.join(_HERE, _name)
    if _name.endswith(_KEPT) and _name != "README.md" and os.path.isfile(_path):
        with open(_path, "rb") as _handle:
            _digest.update(_name.encode() + b"\0" + hashlib.sha256(_handle.read()).digest())
_content_hash = _digest.hexdigest()
print(f"content hash {_content_hash}; predicted seed "
      f"{int(hashlib.sha256(_content_hash.encode()).hexdigest()[:8], 16) & 0x7FFFFFFF}", flush=True)
