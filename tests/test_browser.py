"""The HTML a student and an instructor open, opened in a real browser (headless Chromium): the figures are drawn
and nothing is wider than a 1280 px window.

Chromium loads a copy of the page with a small script appended that, once the page and its images have loaded,
reads every image's decoded size and measures the page, and writes what it found into the page (hidden); ``--dump-dom`` prints the page as the
script left it.  A screenshot at 1280 px is taken as a student would see the page.  Without Chromium (Debian's
``chromium`` package; `.ci/run` installs it) the tests are skipped.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import struct
import subprocess
from pathlib import Path

import pytest

from .batch_fixtures import synthetic_report
from .submissions import build_planted, copy_reference, planted_mistakes

pytestmark = pytest.mark.slow

WIDTH = 1280
BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
#: what the page script writes into the page: each image decoded and its sizes, and the page's widths
MEASURE = """
<script>
window.addEventListener("load", () => {
  const images = [...document.images];
  const decoded = images.map(img => img.complete && img.naturalWidth > 0);
  const root = document.documentElement;
  const wide = [...document.querySelectorAll("body *")]
    .filter(el => el.getBoundingClientRect().right > root.clientWidth + 0.5)
    .map(el => el.tagName.toLowerCase() + (el.id ? "#" + el.id : ""));
  const found = {
    images: images.map((img, k) => ({alt: img.alt, decoded: decoded[k], naturalWidth: img.naturalWidth,
      naturalHeight: img.naturalHeight, shownWidth: img.getBoundingClientRect().width,
      shownHeight: img.getBoundingClientRect().height})),
    scrollWidth: root.scrollWidth, clientWidth: root.clientWidth, innerWidth: window.innerWidth, wide: wide,
    scrolled: [...document.querySelectorAll("body *")].filter(el => el.scrollWidth > el.clientWidth + 1
      && ["auto", "scroll"].includes(getComputedStyle(el).overflowX) && el.tagName !== "PRE")
      .map(el => el.tagName.toLowerCase() + (el.id ? "#" + el.id : "")),
  };
  const out = document.createElement("pre");
  out.id = "browser-measure";
  out.hidden = true;
  out.textContent = JSON.stringify(found);
  document.body.appendChild(out);
});
</script>
"""


def chromium() -> str | None:
    """The Chromium to use: ``$CHROMIUM``, or the first of the usual names on the PATH."""
    named = os.environ.get("CHROMIUM")
    if named:
        return shutil.which(named) or (named if Path(named).exists() else None)
    return next((path for path in map(shutil.which, BROWSERS) if path), None)


@pytest.fixture(scope="module")
def browser():
    path = chromium()
    if path is None:
        pytest.skip("Chromium is not installed (apt-get install chromium; .ci/run installs it): the HTML reports "
                    "are not checked in a browser here")
    return path


def _run(browser: str, page: Path, profile: Path, *extra: str) -> subprocess.CompletedProcess:
    command = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
               "--disable-extensions", "--mute-audio", f"--user-data-dir={profile}",
               f"--window-size={WIDTH},1000", "--virtual-time-budget=15000", *extra, page.as_uri()]
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


def open_page(browser: str, html: str, folder: Path) -> dict:
    """Open ``html`` at 1280 px: what the page script measured, and the screenshot's path."""
    page = folder / "page.html"
    page.write_text(html.replace("</body>", MEASURE + "</body>"), encoding="utf-8")
    dumped = _run(browser, page, folder / "profile", "--dump-dom")
    found = re.search(r'<pre id="browser-measure" hidden="">(.*?)</pre>', dumped.stdout, re.S)
    assert found, (f"the page script left no measurement (exit {dumped.returncode}, {len(dumped.stdout)} characters "
                   f"of page):\n{dumped.stderr[-2000:]}")
    measured = json.loads(found.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">")
                          .replace("&amp;", "&"))
    shot = folder / "screenshot.png"
    taken = _run(browser, folder / "page.html", folder / "profile", f"--screenshot={shot}")
    assert shot.exists(), f"no screenshot (exit {taken.returncode}):\n{taken.stderr[-2000:]}"
    measured["screenshot"] = shot
    return measured


def png_size(path: Path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    return struct.unpack(">II", data[16:24])


def assert_fits(measured: dict) -> None:
    assert measured["clientWidth"] == WIDTH, measured
    assert measured["scrollWidth"] <= WIDTH, (
        f"the page is {measured['scrollWidth']} px wide at {WIDTH} px; too wide: {measured['wide'][:10]}")
    assert not measured["scrolled"], f"these parts scroll sideways at {WIDTH} px: {measured['scrolled']}"
    assert png_size(measured["screenshot"])[0] == WIDTH


def assert_drawn(measured: dict, alts: list[str]) -> None:
    """Every image named is decoded, has pixels, and is shown at a readable size within the window."""
    images = {image["alt"]: image for image in measured["images"]}
    for alt in alts:
        assert alt in images, f"no image {alt!r} among {sorted(images)}"
        image = images[alt]
        assert image["decoded"] and image["naturalWidth"] > 100 and image["naturalHeight"] > 100, image
        assert 300 <= image["shownWidth"] <= WIDTH and image["shownHeight"] > 100, image


# ------------------------------------------------------------------------------------------ a student's report


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """Problems 6 and 8 graded on a submission whose problem 6 has a planted mistake, problem 8 the reference's."""
    from grader.runner import grade_submission

    mistake = next(m for m in planted_mistakes() if m.name == "p06-frames-order")
    folder = build_planted(mistake, tmp_path_factory.mktemp("browser") / "student")
    return grade_submission(folder, [6, 8])


def test_a_report_with_figures_is_drawn_and_fits_1280_px(browser, graded, tmp_path):
    from grader.render import render_html

    figures = [(r.check_id, fig.title) for report in graded for r in report.results for fig in r.figures]
    assert ("p06.frames", "Problem 6: the frames C1, C2, C3 in I") in figures
    assert ("p08.part_c", "Problem 8: the body's axes along the three runs") in figures
    frames = next(r for r in graded[0].results if r.check_id == "p06.frames")
    assert frames.status.value == "failed"  # the figure stands beside the failure it illustrates
    measured = open_page(browser, render_html(graded), tmp_path)
    assert_drawn(measured, [title for _, title in figures])
    assert_fits(measured)


# ------------------------------------------------------------------------------------------ the class summary


def test_the_class_summary_of_a_large_class_fits_1280_px(browser, tmp_path):
    """Forty students over many problems: the gradebook table, the mistakes and the plots stay within the page."""
    from grader.batch.exports import class_summary
    from grader.batch.gradebook import Graded

    numbers = list(range(1, 41))
    graded = []
    for i in range(40):
        for n in numbers:
            report = synthetic_report(n, failed=(1,) if (i + n) % 3 == 0 else (), checks=4)
            graded.append(Graded(f"student_with_a_long_name_{i:03d}", f"hash{i}", f"0.1.0+{n % 2}", 1,
                                 "2024-01-01T00:00:00", "graded", report))
    html = class_summary(graded)
    measured = open_page(browser, html, tmp_path)
    assert_drawn(measured, ["Total score distribution", "Checks failed most often"])
    assert_fits(measured)


def test_the_readme_example_report(browser, tmp_path, capsys):
    """The README's example, `grade problem-8 --html report.html` on a finished submission, opens with its plot."""
    from grader.cli import main

    copy_reference(tmp_path / "mywork")
    main(["problem-8", "--submission", str(tmp_path / "mywork"), "--html", str(tmp_path / "report.html")])
    assert "report.html" in capsys.readouterr().out or (tmp_path / "report.html").exists()
    measured = open_page(browser, (tmp_path / "report.html").read_text(), tmp_path)
    assert_drawn(measured, ["Problem 8: the body's axes along the three runs"])
    assert_fits(measured)
