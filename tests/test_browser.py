"""The HTML a student and an instructor open, opened in a real browser (headless Chromium): the figures are drawn,
nothing is wider than a 1280 px window, and the class summary reads at 1280 px and on a phone (390 px) with no word
broken inside.

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
// The words of the tables' cells that the browser broke across lines.  A word is what lies between white space;
// a line may end after a hyphen, a slash or a dash within one (the places a line is meant to break).  Each piece
// of a word is measured where it was laid out: its boxes on more than one line are a word broken inside.  In a
// <pre> (a student's own text), a piece wider than the <pre> itself may break; any other may not.
function brokenWords() {
  const broken = [];
  for (const cell of document.querySelectorAll("td, th")) {
    const walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const pre = node.parentElement.closest("pre");
      const room = pre ? pre.clientWidth : Infinity;
      const pieces = /[^\\s\\-\\/\\u2013\\u2014]+[\\-\\/\\u2013\\u2014]*|[\\-\\/\\u2013\\u2014]+/g;
      for (let m = pieces.exec(node.data); m; m = pieces.exec(node.data)) {
        const range = document.createRange();
        range.setStart(node, m.index);
        range.setEnd(node, m.index + m[0].length);
        const boxes = [...range.getClientRects()].filter(r => r.width > 0 && r.height > 0);
        const lines = new Set(boxes.map(r => Math.round(r.top)));
        const width = boxes.reduce((sum, r) => sum + r.width, 0);
        if (lines.size > 1 && width <= room) {
          broken.push({word: m[0], cell: cell.tagName.toLowerCase(),
                       table: (cell.closest("table") || {}).id || "", lines: lines.size});
        }
      }
    }
  }
  return broken;
}
window.addEventListener("load", () => {
  document.querySelectorAll("details").forEach(d => { d.open = true; });  // measured as a reader opens them
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
    broken: brokenWords(),
  };
  if (window.parent !== window) {  // in a frame as narrow as a phone: the page around it writes it down
    window.parent.postMessage(JSON.stringify(found), "*");
    return;
  }
  const out = document.createElement("pre");
  out.id = "browser-measure";
  out.hidden = true;
  out.textContent = JSON.stringify(found);
  document.body.appendChild(out);
});
</script>
"""
#: headless Chromium makes no window narrower than this: a phone's width is had in a frame of that width instead,
#: whose page has its own viewport (and media queries) as on the phone
NARROWEST_WINDOW = 500
FRAME = """<!doctype html>
<html><body style="margin: 0">
<iframe src="page.html" style="width: {width}px; height: 1000px; border: 0"></iframe>
<script>
window.addEventListener("message", event => {{
  const out = document.createElement("pre");
  out.id = "browser-measure";
  out.hidden = true;
  out.textContent = event.data;
  document.body.appendChild(out);
}});
</script>
</body></html>
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


def _run(browser: str, page: Path, profile: Path, *extra: str, width: int = WIDTH) -> subprocess.CompletedProcess:
    command = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
               "--disable-extensions", "--mute-audio", f"--user-data-dir={profile}",
               f"--window-size={width},1000", "--virtual-time-budget=15000", *extra, page.as_uri()]
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


def open_page(browser: str, html: str, folder: Path, width: int = WIDTH) -> dict:
    """Open ``html`` in a window ``width`` px wide: what the page script measured, and the screenshot's path (none
    below ``NARROWEST_WINDOW``, where the page is opened in a frame of that width)."""
    folder.mkdir(parents=True, exist_ok=True)
    page = folder / "page.html"
    page.write_text(html.replace("</body>", MEASURE + "</body>"), encoding="utf-8")
    if width < NARROWEST_WINDOW:
        frame = folder / "frame.html"
        frame.write_text(FRAME.format(width=width), encoding="utf-8")
        dumped = _run(browser, frame, folder / "profile", "--dump-dom")
        found = re.search(r'<pre id="browser-measure" hidden="">(.*?)</pre>', dumped.stdout, re.S)
        assert found, f"the page in the frame left no measurement (exit {dumped.returncode}):\n{dumped.stderr[-2000:]}"
        measured = json.loads(found.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">")
                              .replace("&amp;", "&"))
        measured["screenshot"] = None
        return measured
    dumped = _run(browser, page, folder / "profile", "--dump-dom", width=width)
    found = re.search(r'<pre id="browser-measure" hidden="">(.*?)</pre>', dumped.stdout, re.S)
    assert found, (f"the page script left no measurement (exit {dumped.returncode}, {len(dumped.stdout)} characters "
                   f"of page):\n{dumped.stderr[-2000:]}")
    measured = json.loads(found.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">")
                          .replace("&amp;", "&"))
    shot = folder / "screenshot.png"
    taken = _run(browser, folder / "page.html", folder / "profile", f"--screenshot={shot}", width=width)
    assert shot.exists(), f"no screenshot (exit {taken.returncode}):\n{taken.stderr[-2000:]}"
    measured["screenshot"] = shot
    return measured


def png_size(path: Path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    return struct.unpack(">II", data[16:24])


def assert_fits(measured: dict, width: int = WIDTH, scrolling: bool = False) -> None:
    """The page is no wider than the window; no part of it scrolls sideways unless ``scrolling`` (a phone, where a
    wide table scrolls within its own box rather than breaking its words)."""
    assert measured["clientWidth"] == width, measured
    assert measured["scrollWidth"] <= width, (
        f"the page is {measured['scrollWidth']} px wide at {width} px; too wide: {measured['wide'][:10]}")
    assert scrolling or not measured["scrolled"], f"these parts scroll sideways at {width} px: {measured['scrolled']}"
    if measured["screenshot"] is not None:
        assert png_size(measured["screenshot"])[0] == width


def assert_no_broken_word(measured: dict, width: int) -> None:
    broken = measured["broken"]
    assert not broken, f"{len(broken)} words broken inside at {width} px, e.g. {broken[:8]}"


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
    from grader.report.html import render_html

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
    from grader.report.summary import class_summary
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
    """The README's example for a student, `grade problem-8 --html report.html` on a finished submission, opens with
    its plot."""
    from grader.cli import main

    copy_reference(tmp_path / "mywork")
    main(["problem-8", "--submission", str(tmp_path / "mywork"), "--html", str(tmp_path / "report.html")])
    assert "report.html" in capsys.readouterr().out or (tmp_path / "report.html").exists()
    measured = open_page(browser, (tmp_path / "report.html").read_text(), tmp_path)
    assert_drawn(measured, ["Problem 8: the body's axes along the three runs"])
    assert_fits(measured)


PHONE = 390


def summary_class():
    """A class as an instructor meets it: names long and short, the course's problem titles, checks that fail
    (hidden ones too), free-text answers with their scores, and a submission that could not be loaded."""
    from dataclasses import replace

    from grader.batch.gradebook import Graded
    from grader.results import Status

    titles = {6: "Euler angles, Tait-Bryan/Cardan convention", 8: "Integrating angular velocities",
              10: "Understanding rotation matrices", 37: "Robotic Arm. 2 - Controller Evaluation"}
    names = ["alice", "bob", "Zoë Müller-Lüdenscheidt", "student_with_a_long_name_007", "carol", "dave"]
    graded = []
    for i, name in enumerate(names):
        for n, title in titles.items():
            report = synthetic_report(n, failed=(1, 2) if (i + n) % 2 else (), hidden=(3,), checks=5,
                                      manual=n in (8, 10))
            results = tuple(replace(r, check_id=f"p{n:02d}.exponential_orthonormal_{r.check_id[-1]}",
                                    title=f"exponential_step keeps A_IC orthonormal (even for a large step) {k}")
                            for k, r in enumerate(report.results))
            manual = tuple(replace(m, answer="Because its columns are orthonormal unit vectors: A_IB^T A_IB = E.",
                                   score=1.5 if i % 2 else None) for m in report.manual)
            report = replace(report, title=title, results=results, manual=manual)
            if name == "carol":
                report = replace(report, manual=(), load_error=(
                    "carol.zip is not a readable zip archive: File is not a zip file. Make the archive again "
                    "from the folder that `grade init` made (or submit the folder itself)."),
                    results=tuple(replace(r, status=Status.ERROR, score=0.0) for r in results))
            graded.append(Graded(name, f"hash{i}", "0.1.0+1", 1, "2024-01-01T00:00:00", "graded", report))
    return graded


@pytest.mark.parametrize("width", [WIDTH, PHONE])
def test_the_class_summary_breaks_no_word_at_1280_px_or_on_a_phone(browser, tmp_path, width):
    """Headers, names and check ids were broken in the middle ("Proble m", "ali ce", a vertical "S c o r e") at
    1280 px.  No word of a table is broken at 1280 px, nor on a phone, where a wide table scrolls in its own box and
    the page stays within the window."""
    from grader.report.summary import class_summary

    measured = open_page(browser, class_summary(summary_class()), tmp_path / str(width), width=width)
    assert_no_broken_word(measured, width)
    assert_fits(measured, width, scrolling=width < WIDTH)
    assert_drawn(measured, ["Total score distribution", "Checks failed most often"])


# ------------------------------------------------------------------------------------------ figures that read

#: what the page script writes of every figure: the legend's text as shown (its size in the picture, from the
#: image's data-text-px, times the scale at which the picture is shown), the report's text size, and how many pixels
#: of each of the reference's colours (data-reference) the picture shows
FIGURE_MEASURE = """
<script>
window.addEventListener("load", () => {
  const body = parseFloat(getComputedStyle(document.body).fontSize);
  const figures = [...document.querySelectorAll("img[data-text-px]")].map(img => {
    const canvas = document.createElement("canvas");
    canvas.width = img.naturalWidth; canvas.height = img.naturalHeight;
    const context = canvas.getContext("2d");
    context.drawImage(img, 0, 0);
    const pixels = context.getImageData(0, 0, canvas.width, canvas.height).data;
    const colours = img.dataset.reference.split(" ").filter(c => c);
    const counts = colours.map(hex => {
      const rgb = [1, 3, 5].map(i => parseInt(hex.slice(i, i + 2), 16));
      let n = 0;
      for (let k = 0; k < pixels.length; k += 4) {
        if (Math.abs(pixels[k] - rgb[0]) <= 8 && Math.abs(pixels[k + 1] - rgb[1]) <= 8
            && Math.abs(pixels[k + 2] - rgb[2]) <= 8) n++;
      }
      return n;
    });
    const scale = img.getBoundingClientRect().width / img.naturalWidth;
    return {alt: img.alt, legendPx: parseFloat(img.dataset.textPx) * scale, scale: scale,
            reference: Object.fromEntries(colours.map((c, i) => [c, counts[i]]))};
  });
  const out = document.createElement("pre");
  out.id = "figure-measure";
  out.hidden = true;
  out.textContent = JSON.stringify({body: body, figures: figures});
  document.body.appendChild(out);
});
</script>
"""


def test_a_passing_report_shows_legends_at_its_text_size_and_the_reference_under_the_answer(browser, tmp_path):
    """The reference graded: every figure's legend reads at the report's text size (not a few pixels high, as wide
    figures scaled down to the column were), and the reference's line shows around the student's right answer."""
    from grader.report.html import render_html
    from grader.runner import grade_submission

    reports = grade_submission(copy_reference(tmp_path / "ref"), [6, 8, 14, 17])
    assert all(report.score == report.auto_max_score for report in reports)
    html = render_html(reports).replace("</body>", FIGURE_MEASURE + "</body>")
    measured = open_page(browser, html, tmp_path)
    assert_fits(measured)
    dumped = _run(browser, tmp_path / "page.html", tmp_path / "profile", "--dump-dom").stdout
    found = re.search(r'<pre id="figure-measure" hidden="">(.*?)</pre>', dumped, re.S)
    assert found, "the figure script left no measurement"
    data = json.loads(found.group(1).replace("&quot;", '"').replace("&amp;", "&"))
    assert len(data["figures"]) >= 5 and data["body"] >= 12
    small = {f["alt"]: round(f["legendPx"], 1) for f in data["figures"] if f["legendPx"] < 0.85 * data["body"]}
    assert not small, f"legends smaller than the report's text ({data['body']} px): {small}"
    hidden = {f["alt"]: f["reference"] for f in data["figures"]
              if not f["reference"] or min(f["reference"].values()) < 50}
    assert not hidden, f"the reference's lines do not show under a right answer: {hidden}"
