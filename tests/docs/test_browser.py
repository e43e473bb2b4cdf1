"""A real browser opens the reproduction report and built documentation pages (Debian's
chromium, headless, from disk, at 1280 px): the math is typeset (MathML laid out, no raw TeX
left), the report's images are embedded and decode, nothing overflows horizontally, and the
site's search answers from disk.

Each page is copied next to itself with a small probe script that, after the load event,
writes its measurements as JSON into the DOM; ``chromium --dump-dom`` prints that DOM. No
timing is asserted: ``--virtual-time-budget`` lets the page settle, the timeout is generous.
Skipped with a message when no chromium is installed (``.ci/run`` installs it).
"""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

from impactlab.paper.reproduction import reproduce

WIDTH = 1280
CHROMIUM = next(
    (p for p in map(shutil.which, ("chromium", "chromium-browser", "google-chrome")) if p), None
)
pytestmark = pytest.mark.skipif(
    CHROMIUM is None,
    reason="no chromium on PATH: the browser tests need Debian's chromium "
    "(apt-get install chromium; .ci/run installs it when missing)",
)

# Runs after the load event; writes what the test checks into <pre id="impactlab-probe">.
_PROBE = """
<script>
window.addEventListener("load", function () {
  var doc = document.documentElement, body = document.body.cloneNode(true);
  body.querySelectorAll("pre, code, script, style, math, #impactlab-probe")
      .forEach(function (e) { e.remove(); });
  var wide = [];
  document.querySelectorAll("div.arithmatex, .table-wrap, article, .md-content, figure")
      .forEach(function (e) {
        var r = e.getBoundingClientRect();
        if (r.right > window.innerWidth + 1) { wide.push(e.tagName + "." + e.className); }
      });
  var cut = [];  // display formulas that need their scroll bar: cut at the right edge
  document.querySelectorAll("div.arithmatex").forEach(function (e) {
    if (e.scrollWidth > e.clientWidth + 1) { cut.push(e.textContent.slice(0, 40)); }
  });
  var stacked = 0, fracs = document.querySelectorAll("mfrac");
  fracs.forEach(function (f) {
    if (f.children.length === 2) {
      var num = f.children[0].getBoundingClientRect(), den = f.children[1].getBoundingClientRect();
      if (num.bottom <= den.top + 1) { stacked += 1; }
    }
  });
  var images = Array.prototype.map.call(document.images, function (i) {
    return {data: i.src.indexOf("data:") === 0, width: i.naturalWidth,
            right: i.getBoundingClientRect().right};
  });
  var out = document.createElement("pre");
  out.id = "impactlab-probe";
  out.textContent = JSON.stringify({
    innerWidth: window.innerWidth, scrollWidth: doc.scrollWidth,
    math: document.querySelectorAll("math").length, fracs: fracs.length, stacked: stacked,
    text: body.textContent, wide: wide, cut: cut, images: images
  });
  document.body.appendChild(out);
});
</script>
"""


# Types a query into the search box until the search answers (from disk the site's search
# runs through the vendored iframe-worker shim and search/search_index.js), at most 40 tries.
_SEARCH_PROBE = """
<script>
window.addEventListener("load", function () {
  var tries = 0;
  function attempt() {
    var box = document.querySelector("input.md-search__input");
    var meta = document.querySelector(".md-search-result__meta");
    var answer = meta ? meta.textContent : "";
    if (/matching/.test(answer) || tries++ >= 40) {
      var out = document.createElement("pre");
      out.id = "impactlab-probe";
      out.textContent = JSON.stringify({answer: answer,
        items: document.querySelectorAll(".md-search-result__item").length});
      document.body.appendChild(out);
      return;
    }
    if (box) {
      box.focus();
      box.value = "hertz";
      box.dispatchEvent(new Event("input", {bubbles: true}));
      box.dispatchEvent(new KeyboardEvent("keyup", {key: "z", bubbles: true}));
    }
    setTimeout(attempt, 500);
  }
  setTimeout(attempt, 500);
});
</script>
"""


def probe(page: Path, tmp_path: Path, script: str = _PROBE) -> dict[str, Any]:
    """Open ``page`` (a copy next to it, with the probe ``script``) in headless chromium at
    1280 px; the JSON the probe wrote into the DOM."""
    copy = page.with_name(page.stem + ".probe.html")
    copy.write_text(page.read_text(encoding="utf-8").replace("</body>", script + "</body>"))
    assert CHROMIUM is not None
    cmd = [
        CHROMIUM,
        "--headless",
        "--no-sandbox",  # the CI runs as root
        "--disable-gpu",
        "--disable-dev-shm-usage",
        "--hide-scrollbars",
        "--no-first-run",
        f"--user-data-dir={tmp_path / 'chromium-profile'}",
        f"--window-size={WIDTH},900",
        "--virtual-time-budget=30000",
        "--dump-dom",
        copy.as_uri(),
    ]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
    m = re.search(r'<pre id="impactlab-probe">(.*?)</pre>', proc.stdout, re.DOTALL)
    assert m, f"no probe result from chromium (exit {proc.returncode}): {proc.stderr[-2000:]}"
    result: dict[str, Any] = json.loads(html.unescape(m.group(1)))
    return result


def assert_fits(res: dict[str, Any]) -> None:
    assert res["innerWidth"] == WIDTH
    assert res["scrollWidth"] <= WIDTH, f"page {res['scrollWidth']} px wide at {WIDTH} px"
    assert not res["wide"], f"elements past the right edge: {res['wide']}"


def assert_math_typeset(res: dict[str, Any], at_least: int) -> None:
    assert res["math"] >= at_least
    assert not res["cut"], f"display formulas wider than the text column: {res['cut']}"
    assert res["fracs"] > 0 and res["stacked"] == res["fracs"], "fractions not laid out"
    raw = [t for t in ("$$", "\\(", "\\[", "\\frac", "\\delta") if t in res["text"]]
    assert not raw, f"raw TeX in the page's text: {raw}"


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """report.html of the analytic part of the reproduction (its tables and figures)."""
    return reproduce(tmp_path_factory.mktemp("browser_report"), simulate=False).report_html


def test_report_renders_self_contained(report: Path, tmp_path: Path) -> None:
    res = probe(report, tmp_path)
    assert_fits(res)
    assert len(res["images"]) >= 2
    for img in res["images"]:
        assert img["data"] and img["width"] > 0, img  # embedded, and decoded by the browser
        assert img["right"] <= WIDTH


@pytest.mark.parametrize(
    ("page", "formulas"),
    [("engine/index.html", 100), ("laws/ghaednia.html", 7), ("laws/brake.html", 10)],
)
def test_docs_page_renders(site: Path, tmp_path: Path, page: str, formulas: int) -> None:
    res = probe(site / page, tmp_path)
    assert_fits(res)
    assert_math_typeset(res, formulas)


def test_search_works_from_disk(site: Path, tmp_path: Path) -> None:
    res = probe(site / "engine" / "index.html", tmp_path, _SEARCH_PROBE)
    assert "matching" in res["answer"] and res["items"] > 0, res
