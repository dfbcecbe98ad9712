#!/usr/bin/env python3
"""The browser check of covopt's reports (issue 26), run by CTest (label "browser").

For each report kind (simulate, optimize, speed-limit, robot --trajectory, audit), a SAFE and an
UNSAFE run: covopt runs once with --json and --report x.html (one invocation, so the JSON and the
report share their provenance), and the report is opened in headless Chromium:

  DOM        --dump-dom: #verdict's data-safe is the JSON's verdict and its visible word SAFE or
             UNSAFE; #governing-ratio's data-value is the governing ratio computed here from the
             JSON, its visible digits the same number; every input leaf of the JSON (its dotted
             path, e.g. scene.robot.mass_kg) is an element with that data-key and, as data-value,
             the value exactly as the --json output writes it; one <figure class="chart"> per
             expected chart, each with an <svg> that draws something; no <script>.
  console    the same run with --enable-logging=stderr --v=0: any CONSOLE line (a console
             message, a Content-Security-Policy violation, a failed load) is a failure.
  SVG        every <svg> of the HTML file parses as XML and is in the SVG namespace.
  screenshot --screenshot --window-size=1280,H --hide-scrollbars: the pixel statistics of a page
             with text (not blank), and the banner's colour (green for SAFE, red for UNSAFE) in
             the top of the page.
  PDF        covopt ... --json --report x.pdf: pdfinfo's page count in a sane range; pdftotext
             holds the verdict word, the governing ratio's displayed digits, the commit and the
             command of that run's provenance.

Then: no report for a failed run (bad input: exit 2, no file, an existing file untouched); without
a browser on PATH, --report x.pdf is one error (exit 1) and no file while --report x.html works.

A self-test runs first, on hand-made pages that follow the same markup: a good page passes, and a
page with a console.error, a blank page, a wrong data-value, a wrong verdict, a bad <svg>, a banner
of the wrong colour and a PDF without the commit each fail, so none of the checks can pass by
construction. `--self-test` runs only that (it needs Chromium and poppler-utils, not covopt).

Chromium, pdftotext, pdfinfo and PIL (python3-pil) missing is a failure, not a skip:
scripts/install-deps.sh installs them for the tests.

    check_reports.py --covopt build/cli/covopt [--update-docs REPO_ROOT] [--keep DIR]
    check_reports.py --self-test

--update-docs also writes the screenshot of the SAFE optimize report to
REPO_ROOT/docs/images/report-optimize.png (the README shows it).
"""

import argparse
import html.parser
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree

try:
    from PIL import Image, ImageChops, ImageStat
except ImportError:  # reported as a failure by main()
    Image = None

SVG_NAMESPACE = "http://www.w3.org/2000/svg"
CHROMIUM_TIMEOUT_S = 120
COVOPT_TIMEOUT_S = 300

# The screenshot's window: wide as a desktop browser, tall enough to hold the whole report.
WINDOW_WIDTH = 1280
WINDOW_HEIGHT = 7000
# The top of the page in which the verdict banner must show its colour [pixels].
BANNER_SEARCH_HEIGHT = 900

# Pixel statistics of a page that shows something, over the whole screenshot (white included).
# A blank page measures 0 non-white pixels, 1 colour and a luminance deviation of 0 (the
# self-test's blank and white-on-white pages). The self-test's page, a banner, a table of 12
# inputs and one small chart in the 1280 x 7000 window, mostly empty below, measures 2.1 %
# non-white, about 700 colours (anti-aliased text) and a deviation of 13.5; a report has more
# text and larger charts. The thresholds sit far from both: a quarter of the sparsest page's
# share, a fortieth of its colours, a third of its deviation.
MIN_NON_WHITE_SHARE = 0.005   # pixels with a channel below 245
MIN_DISTINCT_COLOURS = 16
MIN_LUMINANCE_STDDEV = 5.0
# The banner: at least this many pixels of the verdict's hue in the top of the page, and more than
# of the other hue (a 4 px border around a ~1200 px wide banner alone is ~10,000 pixels).
MIN_BANNER_PIXELS = 2000

PDF_MIN_PAGES = 1
PDF_MAX_PAGES = 60


class CheckFailed(Exception):
    pass


# --- the expected verdict, ratio, inputs and charts of each kind, from its JSON -----------------


class Num(float):
    """A JSON number that keeps its text as the --json output wrote it."""

    def __new__(cls, text):
        number = float.__new__(cls, text)
        number.text = text
        return number


def load_json(text):
    return json.loads(text, parse_float=Num, parse_int=Num)


def json_text(value):
    """The scalar as the report writes it in data-value: a string's own characters, a number's
    text exactly as in the JSON, true, false, null; an empty object or array as {} or []."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if value is None:
        return "null"
    if isinstance(value, Num):
        return value.text
    if isinstance(value, str):
        return value
    if isinstance(value, dict):
        return "{}"
    if isinstance(value, list):
        return "[]"
    raise CheckFailed("unexpected JSON value %r" % (value,))


def leaves(value, path):
    """The (dotted path, data-value text) of every leaf under value."""
    if isinstance(value, dict) and value:
        for key, child in value.items():
            yield from leaves(child, path + "." + key)
    elif isinstance(value, list) and value:
        for index, child in enumerate(value):
            yield from leaves(child, "%s.%d" % (path, index))
    else:
        yield path, json_text(value)


def numbers(*values):
    return [float(v) for v in values if isinstance(v, float)]


def max_of(values, what):
    if not values:
        raise CheckFailed("the JSON holds no ratio for %s" % what)
    return max(values)


HEAD_RATIOS = ("laceration_ratio", "contusion_ratio", "fracture_ratio", "compression_ratio", "crush_ratio")


def verdict_simulate(j):
    safe = j["safe"]
    ratios = numbers(*[j[k].get("ratio") for k in ("laceration", "contusion", "fracture", "crush")
                       if isinstance(j.get(k), dict)])
    return safe, max_of(ratios, "simulate's laceration, contusion, fracture and crush verdicts")


def verdict_optimize(j):
    rec = j.get("recommendation")
    if isinstance(rec, dict):
        return j["verdict"] == "covering-found" and rec["safe"], float(rec["governing_ratio"])
    # Nothing recommended: the verdict is the bare robot's.
    bare = j["bare_robot"]
    safe = j["verdict"] == "bare-robot-safe"
    return safe, max_of(numbers(*[bare.get(k) for k in HEAD_RATIOS + ("governing_ratio",)]),
                        "the bare robot")


def verdict_speed_limit(j):
    safe = all(row.get("covered_status", row.get("status")) != "no-safe-value" for row in j["rows"])
    ratios = [r for row in j["rows"] for r in numbers(*[row.get(k) for k in HEAD_RATIOS])]
    return safe, max_of(ratios, "the speed-limit rows")


def verdict_trajectory(j):
    safe = j["status"] in ("safe", "at-rest")
    ratios = [r for s in j["samples"]
              for r in numbers(*[s.get(k) for k in HEAD_RATIOS + ("worst_ratio",)])]
    return safe, max_of(ratios, "the trajectory's samples")


def verdict_audit(j):
    safe = j["status"] in ("safe", "at-rest")
    ratio = max_of(numbers(*[c.get("governing_ratio") for c in j["cells"]]), "the audit's cells")
    if isinstance(j.get("limiting"), dict) and isinstance(j["limiting"].get("governing_ratio"), float):
        if float(j["limiting"]["governing_ratio"]) != ratio:
            raise CheckFailed("the audit's limiting.governing_ratio %s is not the largest cell's %r"
                              % (j["limiting"]["governing_ratio"].text, ratio))
    return safe, ratio


# kind: (the JSON's verdict and governing ratio, its top-level input keys (those it has are
# checked), the charts expected: one each, from report/charts.hpp)
KINDS = {
    "simulate": (verdict_simulate, ["scene", "safety_factor", "uncertain_inputs"], 1),
    "optimize": (verdict_optimize,
                 ["scene", "speed_m_per_s", "thickness_m", "safety_factor", "limits", "design_space",
                  "uncertain_inputs", "max_probability", "samples", "seed"], 1),
    "speed-limit": (verdict_speed_limit,
                    ["solve_for", "scene", "safety_factor", "limits", "search_limit",
                     "uncertain_inputs"], 1),
    "robot --trajectory": (verdict_trajectory,
                           ["scene", "safety_factor", "limits", "search_limit", "regions",
                            "joint_names", "sample_count"], 1),
    "audit": (verdict_audit,
              ["robot", "coverings", "contact_area_m2", "reaction_delay_s", "braking_m_per_s2",
               "safety_factor", "sample_count", "surface", "regions"], 1),
}


def expectations(kind, j):
    verdict, input_keys, charts = KINDS[kind]
    safe, ratio = verdict(j)
    inputs = [leaf for key in input_keys if key in j for leaf in leaves(j[key], key)]
    if not any(path.startswith("scene.") or path.startswith("robot.") for path, _ in inputs):
        raise CheckFailed("the %s JSON has no scene or robot inputs" % kind)
    provenance = j.get("provenance")
    if not isinstance(provenance, dict):
        raise CheckFailed("the %s JSON has no provenance block" % kind)
    return {"safe": bool(safe), "ratio": ratio, "inputs": inputs, "charts": charts,
            "commit": provenance.get("commit", ""), "command": provenance.get("command", "")}


# --- the DOM ------------------------------------------------------------------------------------


class Element:
    def __init__(self, tag, attrs, parent):
        self.tag, self.attrs, self.parent = tag, dict(attrs), parent
        self.children, self.text = [], []

    def descendants(self):
        for child in self.children:
            yield child
            yield from child.descendants()

    def all_text(self):
        parts = list(self.text)
        for child in self.children:
            parts.append(child.all_text())
        return " ".join(parts)

    def classes(self):
        return (self.attrs.get("class") or "").split()


VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "param",
        "source", "track", "wbr"}


class TreeBuilder(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.root = Element("#document", {}, None)
        self.current = self.root

    def handle_starttag(self, tag, attrs):
        element = Element(tag, attrs, self.current)
        self.current.children.append(element)
        if tag not in VOID:
            self.current = element

    def handle_startendtag(self, tag, attrs):
        self.current.children.append(Element(tag, attrs, self.current))

    def handle_endtag(self, tag):
        node = self.current
        while node is not None and node.tag != tag:
            node = node.parent
        if node is not None and node.parent is not None:
            self.current = node.parent

    def handle_data(self, data):
        if data.strip():
            self.current.text.append(data.strip())


def parse_dom(text):
    builder = TreeBuilder()
    builder.feed(text)
    builder.close()
    return builder.root


def hidden(element):
    node = element
    while node is not None:
        style = (node.attrs.get("style") or "").replace(" ", "").lower()
        if "hidden" in node.attrs or "display:none" in style or "visibility:hidden" in style:
            return True
        node = node.parent
    return False


def verdict_word(text):
    """SAFE or UNSAFE, whichever stands as a word in text (None for neither or both)."""
    words = set(re.findall(r"\b(UNSAFE|SAFE)\b", text))
    return words.pop() if len(words) == 1 else None


def check_dom(dom_text, expected):
    failures = []
    root = parse_dom(dom_text)
    elements = list(root.descendants())
    by_id = {}
    for e in elements:
        if "id" in e.attrs:
            by_id.setdefault(e.attrs["id"], []).append(e)
    if any(e.tag == "script" for e in elements):
        failures.append("the report has a <script>")

    def the_one(element_id):
        found = by_id.get(element_id, [])
        if len(found) != 1:
            failures.append("%d elements with id=\"%s\" (want 1)" % (len(found), element_id))
            return None
        return found[0]

    v = the_one("verdict")
    if v is not None:
        want = "true" if expected["safe"] else "false"
        if v.attrs.get("data-safe") != want:
            failures.append("#verdict data-safe=%r, the JSON's verdict is %s"
                            % (v.attrs.get("data-safe"), want))
        word = verdict_word(v.all_text())
        want_word = "SAFE" if expected["safe"] else "UNSAFE"
        if word != want_word:
            failures.append("#verdict shows %r, not the one word %s" % (word, want_word))
        if hidden(v):
            failures.append("#verdict is hidden")

    r = the_one("governing-ratio")
    if r is not None:
        try:
            value = float(r.attrs.get("data-value", ""))
        except ValueError:
            value = None
        if value != expected["ratio"]:
            failures.append("#governing-ratio data-value=%r, the JSON's governing ratio is %r"
                            % (r.attrs.get("data-value"), expected["ratio"]))
        shown = re.search(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?", r.all_text())
        if not shown or abs(float(shown.group(0)) / expected["ratio"] - 1) > 5e-4:
            failures.append("#governing-ratio shows %r, not %.4g" % (r.all_text(), expected["ratio"]))
        expected["ratio_shown"] = shown.group(0) if shown else ""

    by_key = {}
    for e in elements:
        if "data-key" in e.attrs:
            by_key.setdefault(e.attrs["data-key"], []).append(e.attrs.get("data-value"))
    missing = [(path, text) for path, text in expected["inputs"] if text not in by_key.get(path, [])]
    for path, text in missing[:10]:
        failures.append("input %s=%r: %s" % (path, text, "shown as %r" % by_key[path]
                                             if path in by_key else "no element with that data-key"))
    if len(missing) > 10:
        failures.append("... and %d more inputs missing" % (len(missing) - 10))

    figures = [e for e in elements if e.tag == "figure" and "chart" in e.classes()]
    if len(figures) != expected["charts"]:
        failures.append("%d <figure class=\"chart\"> (want %d)" % (len(figures), expected["charts"]))
    for index, figure in enumerate(figures, 1):
        svgs = [e for e in figure.descendants() if e.tag == "svg"]
        drawing = [e for s in svgs for e in s.descendants()
                   if e.tag in ("path", "line", "polyline", "polygon", "rect", "circle", "text")]
        if not svgs or len(drawing) < 5:
            failures.append("chart %d has no <svg> that draws (%d svg, %d shapes)"
                            % (index, len(svgs), len(drawing)))
    return failures


def check_console(stderr_text):
    return ["console: " + line.strip()[:300] for line in stderr_text.splitlines() if "CONSOLE" in line]


def inline_svgs(html_text):
    """Every top-level <svg>...</svg> of an HTML text, as written."""
    found, depth, start = [], 0, None
    for m in re.finditer(r"<(/?)svg\b[^>]*?(/?)>", html_text, re.IGNORECASE):
        closing, self_closing = m.group(1) == "/", m.group(2) == "/"
        if not closing:
            if depth == 0:
                start = m.start()
            if self_closing:
                if depth == 0:
                    found.append(html_text[start:m.end()])
                continue
            depth += 1
        elif depth > 0:
            depth -= 1
            if depth == 0:
                found.append(html_text[start:m.end()])
    return found


def check_svgs(html_text, expected_count):
    failures = []
    svgs = inline_svgs(html_text)
    if len(svgs) < expected_count:
        failures.append("%d <svg> in the HTML file, want at least %d" % (len(svgs), expected_count))
    for index, svg in enumerate(svgs, 1):
        try:
            element = ElementTree.fromstring(svg)
        except ElementTree.ParseError as e:
            failures.append("<svg> %d is not XML: %s" % (index, e))
            continue
        if element.tag != "{%s}svg" % SVG_NAMESPACE:
            failures.append("<svg> %d is %r, not in the SVG namespace" % (index, element.tag))
    return failures


# --- the screenshot -----------------------------------------------------------------------------


def pixel_statistics(png):
    image = Image.open(png).convert("RGB")
    width, height = image.size
    # A pixel is non-white when any channel is below 245: the lightest of the channels' masks.
    masks = [band.point(lambda v: 255 if v < 245 else 0) for band in image.split()]
    non_white = ImageChops.lighter(ImageChops.lighter(masks[0], masks[1]), masks[2]).histogram()[255]
    colours = image.getcolors(maxcolors=1 << 20)
    distinct = len(colours) if colours is not None else 1 << 20
    stddev = ImageStat.Stat(image.convert("L")).stddev[0]
    return {"size": (width, height), "non_white_share": non_white / float(width * height),
            "distinct_colours": distinct, "luminance_stddev": stddev}


def banner_pixels(png):
    """(green, red) pixels in the top of the page: the verdict banner's border and word."""
    image = Image.open(png).convert("RGB")
    top = image.crop((0, 0, image.size[0], min(BANNER_SEARCH_HEIGHT, image.size[1])))
    green = red = 0
    for r, g, b in top.getdata():
        if g > r + 40 and g > b + 20:
            green += 1
        elif r > g + 60 and r > b + 60:
            red += 1
    return green, red


def check_screenshot(png, safe):
    failures = []
    stats = pixel_statistics(png)
    if stats["non_white_share"] < MIN_NON_WHITE_SHARE:
        failures.append("screenshot blank: %.4f non-white share < %g"
                        % (stats["non_white_share"], MIN_NON_WHITE_SHARE))
    if stats["distinct_colours"] < MIN_DISTINCT_COLOURS:
        failures.append("screenshot blank: %d distinct colours < %d"
                        % (stats["distinct_colours"], MIN_DISTINCT_COLOURS))
    if stats["luminance_stddev"] < MIN_LUMINANCE_STDDEV:
        failures.append("screenshot blank: luminance deviation %.2f < %g"
                        % (stats["luminance_stddev"], MIN_LUMINANCE_STDDEV))
    green, red = banner_pixels(png)
    want, other = (green, red) if safe else (red, green)
    colour = "green" if safe else "red"
    if want < MIN_BANNER_PIXELS or want <= other:
        failures.append("the %s banner's colour is not at the top: %d green, %d red pixels in the "
                        "top %d px" % ("SAFE" if safe else "UNSAFE", green, red,
                                       BANNER_SEARCH_HEIGHT) + " (want %s)" % colour)
    return failures, stats, (green, red)


# --- running programs ---------------------------------------------------------------------------


def find_chromium():
    chosen = os.environ.get("COVOPT_CHROMIUM")
    if chosen:
        return shutil.which(chosen)
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    return None


def run(argv, timeout, env=None):
    """Runs argv (no shell), stdin /dev/null, in a session of its own killed whole on timeout."""
    process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, env=env, start_new_session=True)
    try:
        out, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        raise CheckFailed("%s did not finish within %d s" % (argv[0], timeout))
    finally:
        try:
            os.killpg(process.pid, signal.SIGKILL)  # what the browser left behind
        except ProcessLookupError:
            pass
    return process.returncode, out.decode("utf-8", "replace"), err.decode("utf-8", "replace")


class Browser:
    def __init__(self, executable, scratch):
        self.executable, self.scratch, self.runs = executable, scratch, 0

    def __call__(self, *arguments):
        self.runs += 1
        home = os.path.join(self.scratch, "browser-%d" % self.runs)
        os.makedirs(home)
        env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(home, "config"),
                   XDG_CACHE_HOME=os.path.join(home, "cache"))
        argv = [self.executable, "--headless", "--disable-gpu"]
        if os.geteuid() == 0:
            argv.append("--no-sandbox")
        argv += ["--user-data-dir=" + os.path.join(home, "profile")] + list(arguments)
        try:
            return run(argv, CHROMIUM_TIMEOUT_S, env)
        finally:
            shutil.rmtree(home, ignore_errors=True)


def file_url(path):
    from urllib.parse import quote
    return "file://" + quote(os.path.abspath(path))


def check_page(browser, html_path, expected, png, screenshot=True, dom=True):
    """Every browser check of one HTML report (the self-test leaves out the screenshot or the
    DOM of a page made to fail the other); returns its failures and the pixel statistics."""
    with open(html_path, encoding="utf-8") as f:
        html_text = f.read()
    failures = []
    if dom:
        failures += check_page_dom(browser, html_path, html_text, expected)
    if not screenshot:
        return failures, None
    code, _, err = browser("--hide-scrollbars", "--window-size=%d,%d" % (WINDOW_WIDTH, WINDOW_HEIGHT),
                           "--screenshot=" + png, file_url(html_path))
    if code != 0 or not os.path.isfile(png):
        failures.append("chromium --screenshot failed (exit %d): %s" % (code, err[-500:]))
        return failures, None
    shot_failures, stats, banner = check_screenshot(png, expected["safe"])
    stats["banner_green_red"] = banner
    return failures + shot_failures, stats


def check_page_dom(browser, html_path, html_text, expected):
    failures = []
    code, dom, err = browser("--enable-logging=stderr", "--v=0", "--dump-dom", file_url(html_path))
    if code != 0 or "<html" not in dom:
        failures.append("chromium --dump-dom failed (exit %d): %s" % (code, err[-500:]))
    else:
        failures += check_dom(dom, expected)
        failures += check_console(err)
    return failures + check_svgs(html_text, expected["charts"])


def squeeze(text):
    return re.sub(r"\s+", "", text)


def check_pdf(pdf, expected, ratio_shown):
    failures = []
    code, info, err = run(["pdfinfo", pdf], 60)
    pages = re.search(r"^Pages:\s+(\d+)", info, re.MULTILINE)
    if code != 0 or not pages:
        return ["pdfinfo failed on %s (exit %d): %s" % (pdf, code, err.strip())], None
    count = int(pages.group(1))
    if not PDF_MIN_PAGES <= count <= PDF_MAX_PAGES:
        failures.append("the PDF has %d pages (want %d..%d)" % (count, PDF_MIN_PAGES, PDF_MAX_PAGES))
    code, text, err = run(["pdftotext", "-layout", pdf, "-"], 60)
    if code != 0:
        return failures + ["pdftotext failed on %s (exit %d): %s" % (pdf, code, err.strip())], count
    word = "SAFE" if expected["safe"] else "UNSAFE"
    if verdict_word(text) != word and not re.search(r"\b%s\b" % word, text):
        failures.append("the PDF's text lacks the verdict %s" % word)
    if word == "SAFE" and re.search(r"\bUNSAFE\b", text.split("\f")[0]):
        failures.append("the first page of a SAFE report says UNSAFE")
    flat = squeeze(text)
    for what, needle in (("governing ratio", ratio_shown), ("commit", expected["commit"]),
                         ("command", expected["command"])):
        if not needle or squeeze(needle) not in flat:
            failures.append("the PDF's text lacks the %s %r" % (what, needle))
    return failures, count


# --- the self-test: hand-made pages in the report's markup ---------------------------------------

SELF_TEST_JSON = """{
  "safe": %(safe)s,
  "laceration": {"value_Pa": 223338.24921288757, "limit_Pa": 1000000.0, "ratio": 0.22333824921288759, "safe": true},
  "contusion": {"value_J_per_m2": 29005.032778243753, "limit_J_per_m2": 25200.0, "ratio": %(ratio)s, "safe": %(safe)s},
  "crush": null,
  "scene": {"robot": {"mass_kg": 10.0, "speed_m_per_s": 2.0, "radius_m": 0.015, "youngs_modulus_Pa": 70000000000.0},
            "covering": {"thickness_m": 0.015, "material": null, "note": "a <b> & 'quoted' \\"one\\""},
            "head": {"mass_kg": 4.5}, "extras": [1e-05, 3], "empty": {}},
  "warnings": [],
  "provenance": {"software": "covopt", "version": "0.1.0",
                 "commit": "0123456789abcdef0123456789abcdef01234567",
                 "command": "covopt simulate --speed 2m/s --json --report /tmp/a-long-file-name.html",
                 "date_utc": "2026-11-26T23:40:12Z", "inputs": []}
}"""


def escape(text):
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;").replace("'", "&#39;"))


SELF_TEST_SVG = """<svg xmlns="http://www.w3.org/2000/svg" width="600" height="300" viewBox="0 0 600 300">
<rect x="0" y="0" width="600" height="300" fill="white"/>
<path d="M50,250 L150,80 L250,200 L350,40 L450,220 L550,120" stroke="#1f5fa8" stroke-width="3" fill="none"/>
<line x1="50" y1="100" x2="550" y2="100" stroke="#c0392b" stroke-dasharray="6,4"/>
<line x1="50" y1="250" x2="550" y2="250" stroke="black"/><line x1="50" y1="20" x2="50" y2="250" stroke="black"/>
<text x="300" y="285" text-anchor="middle" font-size="14">time [ms]</text>
</svg>"""


def self_test_page(j, safe_word, colour, extra="", svg=SELF_TEST_SVG, wrong_value=False,
                   head=""):
    expected = expectations("simulate", j)
    rows = []
    for path, text in expected["inputs"]:
        if wrong_value and path == "scene.robot.mass_kg":
            text = "10"
        rows.append('<tr><td>%s</td><td data-key="%s" data-value="%s">%s</td></tr>'
                    % (escape(path), escape(path), escape(text), escape(text)))
    background, border = {"green": ("#e3f4e8", "#137333"), "red": ("#fde7e5", "#b3261e")}[colour]
    ratio = expected["ratio"]
    provenance = j["provenance"]
    return """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">%s
<title>covopt simulate report</title>
<style>body { font-family: sans-serif; margin: 20px; } .verdict { border: 4px solid %s;
background: %s; color: %s; text-align: center; padding: 12px; } .word { font-size: 40pt;
font-weight: 800; } td { border: 1px solid #ccc; padding: 2px 6px; }</style></head>
<body><h1>Collision safety report: covopt simulate</h1>
<section id="verdict" class="verdict" data-safe="%s"><div class="word">%s</div>
<div>Governing: contusion, ratio <span id="governing-ratio" data-value="%s">%.4g</span></div></section>
<h2>Inputs</h2><table>%s</table>
<figure class="chart"><figcaption>force over time</figcaption>%s</figure>
<h2>Provenance</h2><p>commit <code>%s</code></p><p><code>%s</code></p>%s
</body></html>""" % (head, border, background, border, "true" if safe_word == "SAFE" else "false",
                     safe_word, j["contusion"]["ratio"].text, ratio, "\n".join(rows), svg,
                     escape(provenance["commit"]), escape(provenance["command"]), extra)


def self_test(browser, scratch):
    """Each check passes a good page and fails a bad one. Returns its failures."""
    failures = []
    csp = ("<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
           "style-src 'unsafe-inline'\">")

    def attempt(name, page, j, want_failure_containing=None, pdf=False, screenshot=True, dom=True):
        path = os.path.join(scratch, "self-test-%s.html" % name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(page)
        expected = expectations("simulate", j)
        found, _ = check_page(browser, path, expected, path[:-5] + ".png", screenshot, dom)
        if pdf:
            pdf_path = path[:-5] + ".pdf"
            code, _, err = browser("--no-pdf-header-footer", "--print-to-pdf=" + pdf_path,
                                   file_url(path))
            if code != 0 or not os.path.isfile(pdf_path):
                found.append("chromium --print-to-pdf failed (exit %d): %s" % (code, err[-300:]))
            else:
                found += check_pdf(pdf_path, expected, "%.4g" % expected["ratio"])[0]
        if want_failure_containing is None:
            if found:
                failures.append("self-test %s: a good page failed: %s" % (name, "; ".join(found)))
        elif not any(want_failure_containing in f for f in found):
            failures.append("self-test %s: the check did not catch it (want a failure with %r, got %r)"
                            % (name, want_failure_containing, found))
        else:
            print("self-test %s: caught: %s" % (name, next(f for f in found
                                                          if want_failure_containing in f)))

    unsafe = load_json(SELF_TEST_JSON % {"safe": "false", "ratio": "1.150993364216022"})
    safe = load_json(SELF_TEST_JSON % {"safe": "true", "ratio": "0.718210902333276"})
    attempt("good-unsafe", self_test_page(unsafe, "UNSAFE", "red", head=csp), unsafe, pdf=True)
    attempt("good-safe", self_test_page(safe, "SAFE", "green", head=csp), safe, pdf=True)
    attempt("console-error", self_test_page(
        safe, "SAFE", "green", extra="<script>console.error('self-test error')</script>"),
        safe, "console: ", screenshot=False)
    attempt("csp-violation", self_test_page(
        safe, "SAFE", "green", head=csp, extra="<script>var x = 1;</script>"), safe, "console: ",
        screenshot=False)
    attempt("blank", "<!DOCTYPE html><html><head><meta charset=\"utf-8\"></head><body></body></html>",
            safe, "screenshot blank", dom=False)
    attempt("white-text", self_test_page(safe, "SAFE", "green", head=csp).replace(
        "<body>", "<body style=\"color: white; background: white\"><style>* { color: white !important;"
        " background: white !important; border-color: white !important } svg { display: none }"
        "</style>"), safe, "screenshot blank", dom=False)
    attempt("wrong-value", self_test_page(safe, "SAFE", "green", head=csp, wrong_value=True), safe,
            "input scene.robot.mass_kg='10.0'", screenshot=False)
    attempt("wrong-verdict", self_test_page(unsafe, "SAFE", "green", head=csp), unsafe,
            "#verdict data-safe='true'", screenshot=False)
    attempt("wrong-colour", self_test_page(unsafe, "UNSAFE", "green", head=csp), unsafe,
            "banner's colour", dom=False)
    attempt("svg-no-namespace", self_test_page(
        safe, "SAFE", "green", head=csp,
        svg=SELF_TEST_SVG.replace(' xmlns="http://www.w3.org/2000/svg"', "")), safe,
        "not in the SVG namespace", screenshot=False)
    attempt("svg-not-xml", self_test_page(
        safe, "SAFE", "green", head=csp, svg=SELF_TEST_SVG.replace("time [ms]", "time&nbsp;[ms]")),
        safe, "is not XML", screenshot=False)
    no_commit = load_json(SELF_TEST_JSON % {"safe": "true", "ratio": "0.718210902333276"})
    no_commit["provenance"]["commit"] = "fedcba9876543210fedcba9876543210fedcba98"
    attempt("pdf-without-commit", self_test_page(safe, "SAFE", "green", head=csp), no_commit,
            "the PDF's text lacks the commit", pdf=True, screenshot=False, dom=False)
    return failures


# --- the covopt runs ------------------------------------------------------------------------------


def cases(root):
    urdf = os.path.join(root, "robot/models/franka_fr3.urdf")
    pick = os.path.join(root, "robot/models/franka_fr3_pick.csv")
    robot = ["--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick]
    # A compressible covering (ν 0.3): a solid elastomer (ν >= 0.45) would leave its law at 20 % strain.
    audit = robot + ["--covering-modulus", "0.5MPa", "--covering-poisson", "0.3",
                     "--contact-area", "1cm2", "--flat-face-radius", "20mm"]
    # (name, kind, arguments, safe?). speed-limit has no UNSAFE report within reach: its verdict
    # is UNSAFE only for a row with no safe value, where even 1e-6 m/s (or a vanishing mass) is
    # unsafe, which the head model never finds (every ratio vanishes with the speed).
    runs = [
        ("simulate-safe", "simulate", ["simulate", "--speed", "1m/s"], True),
        ("simulate-unsafe", "simulate", ["simulate", "--speed", "2m/s"], False),
        ("optimize-safe", "optimize", ["optimize"], True),
        ("optimize-unsafe", "optimize", ["optimize", "--max-thickness", "3mm"], False),
        ("speed-limit-safe", "speed-limit",
         ["speed-limit", "--material", "elastomer Shore A60", "--covering-thickness", "20mm",
          "--robot-mass", "1kg,5kg,20kg"], True),
        ("trajectory-safe", "robot --trajectory", ["robot"] + robot, True),
        ("trajectory-unsafe", "robot --trajectory",
         ["robot"] + robot + ["--covering-thickness", "1mm"], False),
        ("audit-safe", "audit", ["audit"] + audit + ["--covering-thickness", "40mm"], True),
        ("audit-unsafe", "audit", ["audit"] + audit + ["--covering-thickness", "10mm"], False),
    ]
    # Bad input, one per kind: exit 2 and no report.
    bad = [
        ["simulate", "--speed", "-1m/s"],
        ["optimize", "--max-thickness", "-3mm"],
        ["speed-limit", "--robot-mass", "-1kg"],
        ["robot"] + robot + ["--covering-thickness", "-1mm"],
        ["audit"] + audit + ["--covering-thickness", "-1mm"],
    ]
    return runs, bad


def run_covopt(covopt, arguments, env=None):
    return run([covopt] + arguments, COVOPT_TIMEOUT_S, env)


def check_case(covopt, browser, scratch, name, kind, arguments, safe, report):
    failures = []
    html_path = os.path.join(scratch, name + ".html")
    code, out, err = run_covopt(covopt, arguments + ["--json", "--report", html_path])
    if code not in (0, 1) or not os.path.isfile(html_path):
        return ["%s: covopt %s --json --report x.html: exit %d, %s" %
                (name, " ".join(arguments), code, err.strip()[-500:])], None
    j = load_json(out)
    expected = expectations(kind, j)
    if expected["safe"] != safe:
        failures.append("%s: the case is meant to be %s, the JSON says %s"
                        % (name, "SAFE" if safe else "UNSAFE", "SAFE" if expected["safe"] else "UNSAFE"))
    png = os.path.join(scratch, name + ".png")
    page_failures, stats = check_page(browser, html_path, expected, png)
    failures += ["%s: %s" % (name, f) for f in page_failures]
    report["cases"][name] = {"kind": kind, "safe": expected["safe"], "ratio": expected["ratio"],
                             "inputs": len(expected["inputs"]), "screenshot": stats}

    pdf = os.path.join(scratch, name + ".pdf")
    code, out, err = run_covopt(covopt, arguments + ["--json", "--report", pdf])
    if code not in (0, 1) or not os.path.isfile(pdf):
        failures.append("%s: covopt --report x.pdf: exit %d, %s" % (name, code, err.strip()[-500:]))
    else:
        pdf_expected = expectations(kind, load_json(out))
        pdf_failures, pages = check_pdf(pdf, pdf_expected, expected.get("ratio_shown", ""))
        failures += ["%s: %s" % (name, f) for f in pdf_failures]
        report["cases"][name]["pdf_pages"] = pages
    return failures, png


def check_failed_runs(covopt, scratch, bad_runs):
    """A failed run writes no report, and leaves an existing file as it was."""
    failures = []
    for index, bad in enumerate(bad_runs):
        name = "%d-%s" % (index, bad[0])
        for extension in ("html", "pdf"):
            fresh = os.path.join(scratch, "failed-%s.%s" % (name, extension))
            code, _, err = run_covopt(covopt, bad + ["--report", fresh])
            if code != 2 or os.path.exists(fresh):
                failures.append("bad input (%s): exit %d (want 2), report %s: %s"
                                % (" ".join(bad), code, "written" if os.path.exists(fresh)
                                   else "not written", err.strip()[-300:]))
            kept = os.path.join(scratch, "kept-%s.%s" % (name, extension))
            with open(kept, "w") as f:
                f.write("the previous report\n")
            code, _, _ = run_covopt(covopt, bad + ["--report", kept])
            with open(kept) as f:
                if code != 2 or f.read() != "the previous report\n":
                    failures.append("bad input (%s): the existing %s was changed" % (" ".join(bad), kept))
            leftovers = [n for n in os.listdir(scratch) if ".tmp-" in n]
            if leftovers:
                failures.append("bad input (%s) left temporaries: %s" % (" ".join(bad), leftovers))
    return failures


def check_without_browser(covopt, scratch, arguments):
    """No browser on PATH: --report x.pdf is one error and exit 1, --report x.html works."""
    failures = []
    bin_dir = os.path.join(scratch, "bin-without-browser")
    os.makedirs(bin_dir, exist_ok=True)
    gnuplot = shutil.which("gnuplot")
    if gnuplot:  # the charts still need gnuplot
        os.symlink(gnuplot, os.path.join(bin_dir, "gnuplot"))
    env = {k: v for k, v in os.environ.items() if k != "COVOPT_CHROMIUM"}
    env["PATH"] = bin_dir
    pdf = os.path.join(scratch, "no-browser.pdf")
    code, out, err = run_covopt(covopt, arguments + ["--report", pdf], env)
    message = ("chromium not found on PATH: install chromium (Debian) to write a PDF report, or "
               "write --report FILE.html")
    lines = [line for line in err.splitlines() if line.strip()]
    if code != 1 or len(lines) != 1 or message not in lines[0] or os.path.exists(pdf):
        failures.append("without a browser, --report x.pdf: exit %d (want 1), stderr %r, file %s"
                        % (code, err, "written" if os.path.exists(pdf) else "not written"))
    html_path = os.path.join(scratch, "no-browser.html")
    code, out, err = run_covopt(covopt, arguments + ["--report", html_path], env)
    if code != 0 or not os.path.isfile(html_path) or "id=\"verdict\"" not in open(html_path).read():
        failures.append("without a browser, --report x.html: exit %d, %s" % (code, err.strip()))
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--covopt", help="the covopt program (build/cli/covopt)")
    parser.add_argument("--self-test", action="store_true",
                        help="only the self-test on hand-made pages (no covopt needed)")
    parser.add_argument("--update-docs", metavar="REPO_ROOT",
                        help="also write REPO_ROOT/docs/images/report-optimize.png")
    parser.add_argument("--keep", metavar="DIR", help="write the reports, screenshots and PDFs here")
    args = parser.parse_args()
    if not args.self_test and not args.covopt:
        parser.error("--covopt is required (or --self-test)")

    missing = []
    chromium = find_chromium()
    if chromium is None:
        missing.append("chromium (Debian package chromium)")
    for tool in ("pdftotext", "pdfinfo"):
        if shutil.which(tool) is None:
            missing.append("%s (Debian package poppler-utils)" % tool)
    if Image is None:
        missing.append("PIL (Debian package python3-pil)")
    if missing:
        print("check_reports: FAILED: missing %s; scripts/install-deps.sh installs them"
              % ", ".join(missing), file=sys.stderr)
        return 1

    start = time.monotonic()
    scratch = args.keep or tempfile.mkdtemp(prefix="covopt-check-reports-")
    os.makedirs(scratch, exist_ok=True)
    browser = Browser(chromium, scratch)
    failures = []
    report = {"cases": {}}
    try:
        failures += self_test(browser, scratch)
        if not args.self_test:
            covopt = os.path.abspath(args.covopt)
            root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
            runs, bad_runs = cases(root)
            for name, kind, arguments, safe in runs:
                case_failures, png = check_case(covopt, browser, scratch, name, kind, arguments,
                                                safe, report)
                failures += case_failures
                if args.update_docs and name == "optimize-safe" and png and os.path.isfile(png):
                    write_docs_image(png, args.update_docs)
            failures += check_failed_runs(covopt, scratch, bad_runs)
            failures += check_without_browser(covopt, scratch, runs[0][2])
    except CheckFailed as e:
        failures.append(str(e))
    finally:
        if not args.keep:
            shutil.rmtree(scratch, ignore_errors=True)
    for name, case in report["cases"].items():
        stats = case.get("screenshot") or {}
        print("%-20s %-6s ratio %-10.4g inputs %4d  non-white %.3f, %6d colours, deviation %5.1f, "
              "banner green/red %s, PDF %s pages"
              % (name, "SAFE" if case["safe"] else "UNSAFE", case["ratio"], case["inputs"],
                 stats.get("non_white_share", 0), stats.get("distinct_colours", 0),
                 stats.get("luminance_stddev", 0), stats.get("banner_green_red"),
                 case.get("pdf_pages")))
    print("check_reports: %d browser runs, %.1f s" % (browser.runs, time.monotonic() - start))
    if failures:
        print("check_reports: FAILED:\n  " + "\n  ".join(failures), file=sys.stderr)
        return 1
    print("check_reports: all checks passed")
    return 0


def write_docs_image(png, repo_root):
    """The top of the report (banner, inputs and the first chart) for the README, as a PNG."""
    target = os.path.join(repo_root, "docs", "images", "report-optimize.png")
    os.makedirs(os.path.dirname(target), exist_ok=True)
    image = Image.open(png).convert("RGB")
    image = image.crop((0, 0, image.size[0], min(image.size[1], DOCS_IMAGE_HEIGHT)))
    image.save(target, optimize=True)
    print("check_reports: wrote %s" % target)


DOCS_IMAGE_HEIGHT = 1800

if __name__ == "__main__":
    sys.exit(main())
