"""The one jinja2 environment of the grader: every report, page and file the grader writes from a template is
rendered here, from the templates of ``grader/report/templates``.

``environment("html")`` escapes what it writes (HTML pages: the reports, the class summary, a PrairieLearn
question), ``environment("text")`` does not (results.json's text, a deployment's scripts), and
``environment("terminal")`` writes every expression through ``grader.terminal.inert``, so that no control character
of a student's text reaches a terminal raw.  Compiled templates are kept in jinja2's own per-user cache (a folder
under the temporary directory that jinja2 makes readable by its owner only and refuses if anyone else owns it), so
that a command compiles a template once rather than at every run.
"""

from __future__ import annotations

from functools import lru_cache

from jinja2 import Environment, FileSystemBytecodeCache, PackageLoader, StrictUndefined, pass_environment
from jinja2.filters import do_indent, do_wordwrap

from ..terminal import inert

__all__ = ["environment", "KINDS"]

#: the kinds of output a template writes
KINDS = ("html", "text", "terminal")


def _fmt(x) -> str:
    return f"{x:g}"


def _make(autoescape: bool, cache_pattern: str, **options) -> Environment:
    try:
        cache = FileSystemBytecodeCache(pattern=cache_pattern)
    except RuntimeError:  # jinja2 cannot tell a folder safe for it (a POSIX system without uids): compiled each run
        cache = None
    env = Environment(
        loader=PackageLoader("grader.report", "templates"),
        bytecode_cache=cache,
        autoescape=autoescape,
        undefined=StrictUndefined,
        trim_blocks=False,
        keep_trailing_newline=True,
        **options,
    )
    env.globals["fmt"] = _fmt
    return env


@lru_cache(maxsize=len(KINDS))
def environment(kind: str) -> Environment:
    """The environment of the templates that write ``kind`` (one of ``KINDS``).  The terminal's compiled templates
    are cached apart from the others': the cache knows a template by its name and text, not by the environment
    that compiled it."""
    if kind == "html":
        return _make(True, "__jinja2_%s.cache")
    if kind == "text":
        return _make(False, "__jinja2_%s.cache")
    if kind != "terminal":
        raise ValueError(f"no environment for {kind!r}: one of {', '.join(KINDS)}")
    env = _make(False, "__jinja2_terminal_%s.cache", finalize=inert)
    # the filters that break text into lines take it inert, so that the line breaks of Python's splitlines (\r,
    # \x0b, \x0c, \x1c-\x1e, \x85) are shown escaped too, rather than turned into lines
    env.filters["indent"] = lambda text, *args, **options: do_indent(inert(text), *args, **options)
    env.filters["wordwrap"] = pass_environment(
        lambda environment, text, *args, **options: do_wordwrap(environment, inert(text), *args, **options))
    return env
