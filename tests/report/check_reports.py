#!/usr/bin/env python3
"""The browser check of covopt's reports (issues 26 and 36), run by CTest (label "browser").

For each report kind (simulate, optimize, speed-limit, robot --trajectory, audit, retime) and state (SAFE,
MARGINAL, UNSAFE, LIMITS), a body-region mode among them, covopt runs with --json, the sign-off
fields (--project, --cell, --assessor, --note) and --report x.html, then with --report x.pdf.
The result's "summary" object is the expectation; the report must show it as it is:

  JSON       "summary".state is the state of its safe and margin at the margin threshold the run
             used (SAFE at or above it, MARGINAL below, UNSAFE, LIMITS for a table of limits);
             its safe verdict and governing ratio agree with the result's own keys.
  DOM        --dump-dom: #page-one holds, in order, the header, #verdict (data-state the summary's
             state, data-safe its verdict, .word the one word SAFE/MARGINAL/UNSAFE/LIMITS and a
             sentence), #margin and #margin-threshold (data-value the summary's margin and the
             threshold), #governing-ratio (data-value and visible digits the governing ratio),
             #governing-case (target, criterion), #judged (targets, standards), #covering,
             #robot, #sign-off (every data-field, the values passed, the version, date and input
             digests, two .signature-line: assessor and approver). Every table.inputs has a
             data-group, the header quantity | value | unit | source, and in every row a
             non-empty unit and source cell; every input leaf of the JSON is a value cell of one
             of them with its data-key (dotted path) and, as data-value, the value exactly as
             --json writes it; "input_sources" is each leaf's source cell. #result-json is a
             closed <details>; #appendix has the data-appendix asked for. One <figure
             class="chart" id="chart-N"> or more, each with an <svg> that draws; no <script>.
  console    the same run with --enable-logging=stderr --v=0: any CONSOLE line (a console
             message, a Content-Security-Policy violation, a failed load) is a failure.
  SVG        every <svg> of the HTML file parses as XML and is in the SVG namespace.
  PDF        pdfinfo's page count (optimize and speed-limit <= 4 pages with the summary appendix,
             the FR3 audit <= 8); page 1 of pdftotext (split on form feeds) carries the state word,
             the margin, the governing case, the project and the sign-off block (Assessor,
             Approver); the whole text the commit and the command of the run's provenance.
             --report-appendix full gives more pages than summary, none no more.
  page 1     pdftoppm's image of page 1: pixel statistics of a page with text (not blank), and the
             banner's colour (green SAFE, amber MARGINAL, red UNSAFE, no green for LIMITS).

Then: no report for a failed run (bad input: exit 2, no file, an existing file untouched); without
a browser on PATH, --report x.pdf is one error (exit 1) and no file while --report x.html works.

A self-test runs first, on hand-made pages in the same markup: good pages pass, and pages each
missing or breaking one element (a console.error, a blank page, a wrong data-value, state, margin
or threshold, each page-one section, the sign-off values and signature lines, a unit or source
cell, an input outside the inputs tables, an open #result-json, a wrong appendix, no chart, a bad
<svg>, a banner of the wrong colour, a page 1 without the verdict or the sign-off, too many pages,
a PDF without the commit) each fail, so none of the checks can pass by construction.
`--self-test` runs only that (it needs Chromium and poppler-utils, not covopt).

Chromium, pdftotext, pdfinfo, pdftoppm and PIL (python3-pil) missing is a failure, not a skip:
scripts/install-deps.sh installs them for the tests.

    check_reports.py --covopt build/cli/covopt [--update-docs REPO_ROOT] [--keep DIR]
    check_reports.py --self-test

--update-docs also writes page 1 of each kind's PDF to REPO_ROOT/docs/images/report-<kind>.png
(docs/guide/report.md and the README show them).
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

# The states of a verdict (result_summary.hpp's VerdictState) and the word a reader sees.
STATE_WORDS = {"safe": "SAFE", "marginal": "MARGINAL", "unsafe": "UNSAFE", "limits": "LIMITS"}
# The report's sections on page 1, in their order, after the header.
PAGE_ONE_SECTIONS = ("verdict", "governing-case", "judged", "covering", "robot", "sign-off")
SIGN_OFF_FIELDS = ("project", "cell", "assessor", "note", "date", "version", "digests")
INPUT_GROUPS = ("robot", "covering", "human", "criteria", "solver", "other")
INPUT_HEADER = ["quantity", "value", "unit", "source"]
APPENDIX_MODES = ("none", "summary", "full")

# The sign-off fields every run passes (an ampersand and quotes, escaped by the report).
SIGN_OFF = {"project": "Cell 4 retrofit & \"pick\"", "cell": "Line 2 / station 7",
            "assessor": "A. Example", "note": "Checked by the browser check."}

# Page 1 as an image: pdftoppm's resolution for the check and for the guide's pictures [dpi].
PAGE_IMAGE_DPI = 100
DOCS_IMAGE_DPI = 80
# The part of page 1, from the top, in which the verdict banner must show its colour.
BANNER_SEARCH_SHARE = 0.5

# Pixel statistics of a page that shows something (white included). A blank page measures 0
# non-white pixels, 1 colour and a luminance deviation of 0 (the self-test's blank and
# white-on-white pages). The self-test's page 1 at 100 dpi, the sparsest page checked, measures
# about 6 % non-white, several hundred colours (anti-aliased text) and a deviation above 30; a
# report's page 1 has more. The thresholds sit far from both.
MIN_NON_WHITE_SHARE = 0.005   # pixels with a channel below 245
MIN_DISTINCT_COLOURS = 16
MIN_LUMINANCE_STDDEV = 5.0
# The banner: at least this many pixels of the state's hue in the top of page 1, and more than of
# any other hue (a 4 px border around a banner across an A4 page at 100 dpi alone is ~5,000).
MIN_BANNER_PIXELS = 1500

# Page counts: any report within these; optimize and speed-limit (appendix summary) within 4,
# the FR3 audit within 8 (the cases say which).
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
    """The head's verdict, or with --body-region each region's (and the head's, when judged)."""
    def head_ratios(head):
        return numbers(*[head[k].get("ratio") for k in ("laceration", "contusion", "fracture", "crush")
                         if isinstance(head.get(k), dict)])
    ratios = head_ratios(j)
    if isinstance(j.get("head"), dict):
        ratios += head_ratios(j["head"])
    ratios += numbers(*[r.get("governing_ratio") for r in j.get("regions") or [] if isinstance(r, dict)])
    return j["safe"], max_of(ratios, "simulate's verdicts")


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


def verdict_retime(j):
    safe = j["status"] in ("safe", "at-rest")
    audit = j["after"] if isinstance(j.get("after"), dict) else None
    if audit is None:
        raise CheckFailed("the retime result has no re-audit (after) to report")
    return safe, max_of(numbers(*[c.get("governing_ratio") for c in audit["cells"]]), "the re-audit's cells")


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
    "retime": (verdict_retime,
               ["robot", "coverings", "contact_area_m2", "reaction_delay_s", "braking_m_per_s2",
                "safety_factor", "sample_count", "surface", "regions", "joint_names", "joint_speed_limits_rad_per_s",
                "joint_acceleration_limits_rad_per_s2", "max_speed_scale", "tolerance"], 1),
}


def state_at(summary, threshold):
    """The state of the summary's verdict at the margin threshold (VerdictStateOf): a table of
    limits is LIMITS, or UNSAFE with a case without a safe value; a verdict UNSAFE, SAFE with a
    margin at or above the threshold, else MARGINAL."""
    if summary.get("kind") == "limits":
        return "limits" if summary.get("safe") else "unsafe"
    if not summary.get("evaluated"):
        return "not-evaluated"
    if not summary.get("safe"):
        return "unsafe"
    margin = summary.get("margin")
    return "safe" if isinstance(margin, float) and margin >= threshold else "marginal"


def the_summary(kind, j):
    summary = j.get("summary")
    if not isinstance(summary, dict):
        raise CheckFailed("the %s JSON has no \"summary\" object" % kind)
    for key in ("kind", "safe", "state", "margin", "margin_threshold", "governing", "targets",
                "criteria", "standards", "covering", "robot"):
        if key not in summary:
            raise CheckFailed("the %s JSON's summary has no %r" % (kind, key))
    return summary


def expectations(kind, j, threshold=0.1, appendix="summary", sign_off=None):
    """What the report of the result j must show, and the JSON's own inconsistencies."""
    verdict, input_keys, charts = KINDS[kind]
    summary = the_summary(kind, j)
    failures = []
    # The JSON's state is at its own threshold (the default); the report's at the one it was given.
    own = summary["margin_threshold"]
    if not isinstance(own, float) or summary["state"] != state_at(summary, float(own)):
        failures.append("the summary's state %r is not that of its safe %s and margin %s at its "
                        "threshold %s" % (summary["state"], summary["safe"],
                                          json_text(summary["margin"]), json_text(own)))
    state = state_at(summary, threshold)
    governing = summary["governing"] if isinstance(summary["governing"], dict) else {}
    ratio = governing.get("ratio")
    if summary["kind"] != "limits":
        safe, own_ratio = verdict(j)
        if bool(safe) != bool(summary["safe"]):
            failures.append("the summary's safe %s is not the result's verdict %s"
                            % (summary["safe"], safe))
        # The summary's governing row may be a design rule (the law's validity) above every
        # injury ratio, never below the largest of them.
        if not isinstance(ratio, float) or ratio < own_ratio * (1 - 1e-12):
            failures.append("the summary's governing ratio %s is below the result's largest ratio %r"
                            % (json_text(ratio), own_ratio))
    inputs = [leaf for key in input_keys if key in j for leaf in leaves(j[key], key)]
    if not any(path.startswith("scene.") or path.startswith("robot.") for path, _ in inputs):
        raise CheckFailed("the %s JSON has no scene or robot inputs" % kind)
    provenance = j.get("provenance")
    if not isinstance(provenance, dict):
        raise CheckFailed("the %s JSON has no provenance block" % kind)
    sources = j.get("input_sources")
    if not isinstance(sources, dict) or not sources:
        failures.append("the %s JSON has no \"input_sources\" object" % kind)
    return {"state": state, "safe": bool(summary["safe"]), "summary": summary,
            "ratio": float(ratio) if isinstance(ratio, float) else None,
            "ratio_text": json_text(ratio), "margin": summary["margin"], "threshold": threshold,
            "appendix": appendix, "sign_off": dict(SIGN_OFF if sign_off is None else sign_off),
            "inputs": inputs, "sources": sources if isinstance(sources, dict) else {},
            "charts": charts, "provenance": provenance, "json_failures": failures,
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


def squeeze(text):
    return re.sub(r"\s+", "", text)


def holds(text, needle):
    """needle is in text, whitespace and case aside."""
    return squeeze(needle).lower() in squeeze(text).lower()


def shown_number(text):
    """The first number shown in text, and half a unit of its last digit (0.5 for "28 %",
    0.0005 for "0.718"); a number in per cent is read as a fraction. None when there is none."""
    m = re.search(r"([-+−]?)(\d+(?:\.(\d+))?)(?:[eE]([-+]?\d+))?\s*(%?)", text)
    if not m:
        return None
    value = float(m.group(2)) * (-1 if m.group(1) in ("-", "−") else 1)
    half_unit = 0.5 * 10.0 ** -len(m.group(3) or "")
    if m.group(4):
        value, half_unit = value * 10.0 ** int(m.group(4)), half_unit * 10.0 ** int(m.group(4))
    if m.group(5):
        value, half_unit = value / 100, half_unit / 100
    return value, half_unit


def check_number(failures, element, what, want, want_text):
    """element's data-value is the number want (None: null) and it shows it, as rounded."""
    got = element.attrs.get("data-value")
    if want is None:
        if got != "null":
            failures.append("%s data-value=%r, the summary's is null" % (what, got))
        return ""
    try:
        same = float(got) == float(want)
    except (TypeError, ValueError):
        same = False
    if not same:
        failures.append("%s data-value=%r, the summary's is %s" % (what, got, want_text))
    shown = shown_number(element.all_text())
    if shown is None or abs(shown[0] - float(want)) > shown[1] * 1.001 + 1e-12 * abs(float(want)):
        failures.append("%s shows %r, not %s" % (what, element.all_text(), want_text))
    return element.all_text()


def check_sign_off(failures, sign_off, expected):
    fields = {}
    for e in sign_off.descendants():
        if e.tag == "dd" and "data-field" in e.attrs:
            fields.setdefault(e.attrs["data-field"], []).append(e.all_text())
    for field in SIGN_OFF_FIELDS:
        if len(fields.get(field, [])) != 1:
            failures.append("#sign-off has %d <dd data-field=\"%s\"> (want 1)"
                            % (len(fields.get(field, [])), field))
    for field, value in expected["sign_off"].items():
        if field in fields and squeeze(fields[field][0]) != squeeze(value):
            failures.append("#sign-off %s is %r, not the %r passed" % (field, fields[field][0], value))
    provenance = expected["provenance"]
    for field, needle in (("version", provenance.get("version", "")),
                          ("date", provenance.get("date_utc", "")[:10])):
        if field in fields and not holds(fields[field][0], needle):
            failures.append("#sign-off %s %r lacks %r" % (field, fields[field][0], needle))
    for item in provenance.get("inputs") or []:
        digest = item.get("sha256", "")[:12]
        if "digests" in fields and not holds(fields["digests"][0], digest):
            failures.append("#sign-off digests lack %s's sha256 %s..." % (item.get("path"), digest))
    lines = [e for e in sign_off.descendants() if "signature-line" in e.classes()]
    roles = sorted(e.attrs.get("data-role", "") for e in lines)
    if roles != ["approver", "assessor"]:
        failures.append("#sign-off has signature lines %r (want assessor and approver)" % roles)
    for role in ("Assessor", "Approver"):
        if not re.search(r"\b%s\b" % role, sign_off.all_text()):
            failures.append("#sign-off does not say %s" % role)


def check_page_one(failures, by_id, page_one, elements, expected):
    """#page-one holds the header and the sections in their order; each says what it must."""
    order = {id(e): i for i, e in enumerate(elements)}
    inside = {id(e) for e in page_one.descendants()}
    if not any(e.tag in ("h1", "header") for e in page_one.descendants()):
        failures.append("#page-one has no header")
    previous = -1
    for name in PAGE_ONE_SECTIONS:
        found = by_id.get(name, [])
        if len(found) != 1:
            continue  # counted by the caller
        if id(found[0]) not in inside:
            failures.append("#%s is not on page one (#page-one)" % name)
        elif order[id(found[0])] < previous:
            failures.append("#%s is out of order on page one (want %s)"
                            % (name, ", ".join(PAGE_ONE_SECTIONS)))
        previous = max(previous, order[id(found[0])])
    summary = expected["summary"]
    text = {name: by_id[name][0].all_text() for name in PAGE_ONE_SECTIONS if len(by_id.get(name, [])) == 1}
    governing = summary["governing"] if isinstance(summary["governing"], dict) else {}
    if "governing-case" in text:
        for key in ("target", "criterion"):
            if governing.get(key) and not holds(text["governing-case"], governing[key]):
                failures.append("#governing-case lacks the governing %s %r" % (key, governing[key]))
    if "judged" in text:
        for what in ("targets", "standards"):
            items = list(summary[what] or [])
            # A long list of targets (an audit's 29 regions) is cut on page 1: the first ones,
            # then "and N more"; the N left out must be the rest of the summary's list.
            more = re.search(r"and (\d+) more", text["judged"]) if what == "targets" else None
            if more:
                left_out = int(more.group(1))
                if not 0 < left_out < len(items):
                    failures.append("#judged says %d more of %d targets" % (left_out, len(items)))
                    left_out = 0
                items = items[:len(items) - left_out]
            for item in items:
                if not holds(text["judged"], item):
                    failures.append("#judged lacks the %s %r" % (what[:-1], item))
    covering = summary["covering"]
    if "covering" in text and isinstance(covering, dict):
        if covering.get("material") and not holds(text["covering"], covering["material"]):
            failures.append("#covering lacks the material %r" % covering["material"])
        if isinstance(covering.get("thickness_m"), float):
            mm = float(covering["thickness_m"]) * 1000
            shown = [float(x) for x in re.findall(r"(\d+(?:\.\d+)?)\s*mm", text["covering"])]
            if not any(abs(x - mm) <= 0.005 * mm + 0.05 for x in shown):
                failures.append("#covering does not show the thickness %.4g mm" % mm)
    robot = summary["robot"]
    if "robot" in text and isinstance(robot, dict) and robot.get("model_file"):
        if not holds(text["robot"], os.path.basename(robot["model_file"])):
            failures.append("#robot lacks the model file %r" % robot["model_file"])
    if len(by_id.get("sign-off", [])) == 1:
        check_sign_off(failures, by_id["sign-off"][0], expected)


def check_verdict(failures, v, expected):
    want = STATE_WORDS.get(expected["state"], expected["state"].upper())
    if v.attrs.get("data-state") != expected["state"]:
        failures.append("#verdict data-state=%r, the summary's state is %r"
                        % (v.attrs.get("data-state"), expected["state"]))
    if v.attrs.get("data-safe") != ("true" if expected["safe"] else "false"):
        failures.append("#verdict data-safe=%r, the summary's safe is %s"
                        % (v.attrs.get("data-safe"), expected["safe"]))
    words = [e for e in v.descendants() if e.tag == "div" and "word" in e.classes()]
    if len(words) != 1 or words[0].all_text().strip() != want:
        failures.append("#verdict shows %r, not the one word %s"
                        % ([w.all_text() for w in words], want))
    rest = v.all_text().replace(want, "", 1)
    if len(re.findall(r"[A-Za-z]{2,}", rest)) < 4:
        failures.append("#verdict has no sentence beside the word %s" % want)
    if hidden(v):
        failures.append("#verdict is hidden")


def check_inputs(failures, elements, expected):
    """The inputs tables: group, header, a unit and a source in every row, every input leaf."""
    tables = [e for e in elements if e.tag == "table" and "inputs" in e.classes()]
    if not tables:
        failures.append("no <table class=\"inputs\">")
    by_key = {}
    for table in tables:
        group = table.attrs.get("data-group")
        if group not in INPUT_GROUPS:
            failures.append("table.inputs data-group=%r (want one of %s)" % (group, ", ".join(INPUT_GROUPS)))
        header = [e.all_text().strip().lower() for e in table.descendants() if e.tag == "th"]
        if header[:4] != INPUT_HEADER:
            failures.append("table.inputs[data-group=%s] header %r (want %s)"
                            % (group, header, " | ".join(INPUT_HEADER)))
        for row in (e for e in table.descendants() if e.tag == "tr"):
            cells = [e for e in row.children if e.tag == "td"]
            if not cells:
                continue
            keyed = [c for c in cells if "data-key" in c.attrs]
            what = keyed[0].attrs["data-key"] if keyed else row.all_text()[:60]
            for role in ("unit", "source"):
                cell = [c for c in cells if role in c.classes()]
                if len(cell) != 1 or not cell[0].all_text().strip():
                    failures.append("input %s: no %s (%d cells of class %s, %r)"
                                    % (what, role, len(cell), role, [c.all_text() for c in cell]))
            source = [c.all_text().strip() for c in cells if "source" in c.classes()]
            for cell in keyed:
                by_key.setdefault(cell.attrs["data-key"], []).append(
                    (cell.attrs.get("data-value"), source[0] if source else ""))
    missing = [(path, text) for path, text in expected["inputs"]
               if text not in [value for value, _ in by_key.get(path, [])]]
    for path, text in missing[:10]:
        failures.append("input %s=%r: %s" % (path, text, "shown as %r" % [v for v, _ in by_key[path]]
                                             if path in by_key else "not in an inputs table"))
    if len(missing) > 10:
        failures.append("... and %d more inputs missing" % (len(missing) - 10))
    for path, source in sorted(expected["sources"].items()):
        got = [s for _, s in by_key.get(path, [])]
        if not got:
            failures.append("input %s (source %r) is not in an inputs table" % (path, source))
        elif any(squeeze(s) != squeeze(source) for s in got):
            failures.append("input %s: source %r, the JSON's input_sources says %r" % (path, got[0], source))


def check_charts(failures, elements, expected):
    figures = [e for e in elements if e.tag == "figure" and "chart" in e.classes()]
    if len(figures) < expected["charts"]:
        failures.append("%d <figure class=\"chart\"> (want %d or more)" % (len(figures), expected["charts"]))
    for index, figure in enumerate(figures, 1):
        if figure.attrs.get("id") != "chart-%d" % index:
            failures.append("chart %d has id %r (want chart-%d)" % (index, figure.attrs.get("id"), index))
        svgs = [e for e in figure.descendants() if e.tag == "svg"]
        drawing = [e for s in svgs for e in s.descendants()
                   if e.tag in ("path", "line", "polyline", "polygon", "rect", "circle", "text")]
        if len(svgs) != 1 or len(drawing) < 5:
            failures.append("chart %d has no one <svg> that draws (%d svg, %d shapes)"
                            % (index, len(svgs), len(drawing)))


def check_dom(dom_text, expected):
    failures = list(expected["json_failures"])
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

    for name in ("page-one",) + PAGE_ONE_SECTIONS + ("margin", "margin-threshold", "governing-ratio",
                                                      "result-json", "appendix"):
        the_one(name)
    if len(by_id.get("page-one", [])) == 1:
        check_page_one(failures, by_id, by_id["page-one"][0], elements, expected)
    if len(by_id.get("verdict", [])) == 1:
        check_verdict(failures, by_id["verdict"][0], expected)
    for name, want, want_text in (("margin", expected["margin"], json_text(expected["margin"])),
                                  ("margin-threshold", expected["threshold"], "%g" % expected["threshold"]),
                                  ("governing-ratio", expected["ratio"], expected["ratio_text"])):
        if len(by_id.get(name, [])) == 1:
            shown = check_number(failures, by_id[name][0], "#" + name, want, want_text)
            expected[name.replace("-", "_") + "_shown"] = shown
    if len(by_id.get("page-one", [])) == 1:
        page_one = list(by_id["page-one"][0].descendants())
        for name in ("margin", "margin-threshold", "governing-ratio"):
            if len(by_id.get(name, [])) == 1 and not any(e is by_id[name][0] for e in page_one):
                failures.append("#%s is not on page one (#page-one)" % name)
    details = by_id.get("result-json", [])
    if len(details) == 1:
        if details[0].tag != "details" or "open" in details[0].attrs:
            failures.append("#result-json is a%s <%s>, not a closed <details>"
                            % ("n open" if "open" in details[0].attrs else "", details[0].tag))
        if expected["commit"] and expected["commit"] not in details[0].all_text():
            failures.append("#result-json does not hold the result's JSON (no commit %s)" % expected["commit"])
    appendix = by_id.get("appendix", [])
    if len(appendix) == 1 and appendix[0].attrs.get("data-appendix") != expected["appendix"]:
        failures.append("#appendix data-appendix=%r (want %r)"
                        % (appendix[0].attrs.get("data-appendix"), expected["appendix"]))
    check_inputs(failures, elements, expected)
    check_charts(failures, elements, expected)
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


# --- page 1 as an image -------------------------------------------------------------------------


def pixel_statistics(image):
    width, height = image.size
    # A pixel is non-white when any channel is below 245: the lightest of the channels' masks.
    masks = [band.point(lambda v: 255 if v < 245 else 0) for band in image.split()]
    non_white = ImageChops.lighter(ImageChops.lighter(masks[0], masks[1]), masks[2]).histogram()[255]
    colours = image.getcolors(maxcolors=1 << 20)
    distinct = len(colours) if colours is not None else 1 << 20
    stddev = ImageStat.Stat(image.convert("L")).stddev[0]
    return {"size": (width, height), "non_white_share": non_white / float(width * height),
            "distinct_colours": distinct, "luminance_stddev": stddev}


def hue(r, g, b):
    """green, amber, red or None: the banner's hues (amber before red: both have red above green)."""
    if g > r + 40 and g > b + 20:
        return "green"
    if r > 120 and b < 0.5 * r and 0.45 * r <= g <= 0.85 * r:
        return "amber"
    if r > g + 60 and r > b + 60:
        return "red"
    return None


def banner_pixels(image):
    """The pixels of each hue in the top of page 1: the verdict banner's border and word."""
    top = image.crop((0, 0, image.size[0], int(image.size[1] * BANNER_SEARCH_SHARE)))
    counts = {"green": 0, "amber": 0, "red": 0}
    for colour, count in ((hue(*rgb), n) for n, rgb in top.getcolors(maxcolors=1 << 24)):
        if colour:
            counts[colour] += count
    return counts


BANNER_HUES = {"safe": "green", "marginal": "amber", "unsafe": "red"}


def check_page_image(png, state):
    failures = []
    image = Image.open(png).convert("RGB")
    stats = pixel_statistics(image)
    if stats["non_white_share"] < MIN_NON_WHITE_SHARE:
        failures.append("page 1 blank: %.4f non-white share < %g"
                        % (stats["non_white_share"], MIN_NON_WHITE_SHARE))
    if stats["distinct_colours"] < MIN_DISTINCT_COLOURS:
        failures.append("page 1 blank: %d distinct colours < %d"
                        % (stats["distinct_colours"], MIN_DISTINCT_COLOURS))
    if stats["luminance_stddev"] < MIN_LUMINANCE_STDDEV:
        failures.append("page 1 blank: luminance deviation %.2f < %g"
                        % (stats["luminance_stddev"], MIN_LUMINANCE_STDDEV))
    counts = banner_pixels(image)
    stats["banner"] = counts
    want = BANNER_HUES.get(state)
    if want is None:  # LIMITS: a table of limits is not a green SAFE
        if counts["green"] >= MIN_BANNER_PIXELS:
            failures.append("the %s banner is green: %r pixels in the top of page 1"
                            % (STATE_WORDS.get(state, state), counts))
    elif counts[want] < MIN_BANNER_PIXELS or any(counts[want] <= n for c, n in counts.items() if c != want):
        failures.append("the %s banner's colour is not at the top of page 1: %r pixels (want %s)"
                        % (STATE_WORDS.get(state, state), counts, want))
    return failures, stats


def page_image(pdf, png, dpi):
    """pdftoppm's PNG of page 1 of pdf, written to png."""
    code, _, err = run(["pdftoppm", "-png", "-r", str(dpi), "-f", "1", "-l", "1", "-singlefile",
                        pdf, png[:-4]], 60)
    if code != 0 or not os.path.isfile(png):
        raise CheckFailed("pdftoppm failed on %s (exit %d): %s" % (pdf, code, err.strip()))
    return png


# --- the PDF ------------------------------------------------------------------------------------


def pdf_pages(pdf):
    code, info, err = run(["pdfinfo", pdf], 60)
    pages = re.search(r"^Pages:\s+(\d+)", info, re.MULTILINE)
    if code != 0 or not pages:
        raise CheckFailed("pdfinfo failed on %s (exit %d): %s" % (pdf, code, err.strip()))
    return int(pages.group(1))


def check_pdf(pdf, expected, max_pages=PDF_MAX_PAGES):
    """The page count, page 1 (state, margin, governing case, sign-off) and the provenance;
    returns the failures and the page count."""
    failures = []
    count = pdf_pages(pdf)
    if not PDF_MIN_PAGES <= count <= max_pages:
        failures.append("the PDF has %d pages (want %d..%d)" % (count, PDF_MIN_PAGES, max_pages))
    code, text, err = run(["pdftotext", pdf, "-"], 60)
    if code != 0:
        return failures + ["pdftotext failed on %s (exit %d): %s" % (pdf, code, err.strip())], count
    page_one = text.split("\f")[0]
    word = STATE_WORDS.get(expected["state"], expected["state"].upper())
    if not re.search(r"\b%s\b" % word, page_one):
        failures.append("page 1 of the PDF lacks the state %s" % word)
    for other in STATE_WORDS.values():
        if other != word and re.search(r"\b%s\b" % other, page_one):
            failures.append("page 1 of the %s PDF says %s" % (word, other))
    governing = expected["summary"]["governing"] or {}
    needles = [("governing %s" % key, governing.get(key) or "") for key in ("target", "criterion")]
    needles += [("margin", expected.get("margin_shown", "")),
                ("word", "Margin" if expected["margin"] is not None else ""),
                ("governing ratio", expected.get("governing_ratio_shown", "")),
                ("project", expected["sign_off"].get("project", "")),
                ("assessor", expected["sign_off"].get("assessor", "")),
                ("word", "Assessor"), ("word", "Approver")]
    for what, needle in needles:
        if needle and not holds(page_one, needle):
            failures.append("page 1 of the PDF lacks the %s %r" % (what, needle))
    # The provenance in the layout's text: the reading order joins a line ending in a hyphen to
    # the next one without it ("--robot" broken after "-" reads "-robot").
    code, layout, err = run(["pdftotext", "-layout", pdf, "-"], 60)
    if code != 0:
        return failures + ["pdftotext -layout failed on %s (exit %d): %s" % (pdf, code, err.strip())], count
    for what, needle in (("commit", expected["commit"]), ("command", expected["command"])):
        if not needle or not holds(layout, needle):
            failures.append("the PDF's text lacks the %s %r" % (what, needle))
    return failures, count


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


def check_page(browser, html_path, expected, in_browser=True):
    """The DOM (as Chromium loads it, or for the self-test's markup-only pages as written), the
    console and the SVG of one HTML report; returns its failures."""
    with open(html_path, encoding="utf-8") as f:
        html_text = f.read()
    failures = []
    if not in_browser:
        failures += check_dom(html_text, expected)
    else:
        code, dom, err = browser("--enable-logging=stderr", "--v=0", "--dump-dom", file_url(html_path))
        if code != 0 or "<html" not in dom:
            failures.append("chromium --dump-dom failed (exit %d): %s" % (code, err[-500:]))
        else:
            failures += check_dom(dom, expected)
            failures += check_console(err)
    return failures + check_svgs(html_text, expected["charts"])


def check_printed(pdf, expected, max_pages, png):
    """The PDF's text and its page 1 as an image; returns the failures, pages and statistics."""
    failures, pages = check_pdf(pdf, expected, max_pages)
    image_failures, stats = check_page_image(page_image(pdf, png, PAGE_IMAGE_DPI), expected["state"])
    return failures + image_failures, pages, stats


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
  "summary": {"kind": "verdict", "command": "simulate", "evaluated": true, "safe": %(safe)s,
              "state": "%(state)s", "safety_factor": 1.0, "margin": %(margin)s, "margin_threshold": 0.1,
              "governing": {"target": "head (frontal)", "criterion": "contusion", "ratio": %(ratio)s,
                            "case": "at the peak of the impact"},
              "targets": ["head (frontal)"], "criteria": ["laceration", "contusion"],
              "standards": ["Park et al. 2011"], "scope": ["Skin injury of the head, not ISO/TS 15066."],
              "covering": {"material": "elastomer Shore A60", "thickness_m": 0.015, "law": "hertz",
                           "validity": "within", "validity_ratio": 0.25},
              "robot": {"model_file": "", "motion": "", "joints": [], "reflected_mass_kg": 10.0,
                        "payload_kg": 0.0, "speed_m_per_s": 2.0},
              "rows": [], "limits": []},
  "input_sources": {"scene.robot.mass_kg": "flag --robot-mass", "scene.robot.speed_m_per_s": "flag --speed",
                    "scene.covering.thickness_m": "scene file s.toml"},
  "provenance": {"software": "covopt", "version": "0.1.0",
                 "commit": "0123456789abcdef0123456789abcdef01234567",
                 "command": "covopt simulate --speed 2m/s --json --report /tmp/a-long-file-name.html",
                 "date_utc": "2026-11-26T23:40:12Z",
                 "inputs": [{"role": "scene", "path": "s.toml", "size_bytes": 120,
                             "sha256": "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08"}]}
}"""

# state: (safe, contusion ratio, margin, banner colour)
SELF_TEST_STATES = {"safe": ("true", "0.718210902333276", "0.281789097666724", "green"),
                    "marginal": ("true", "0.951234567890123", "0.048765432109877", "amber"),
                    "unsafe": ("false", "1.150993364216022", "-0.150993364216022", "red")}
SELF_TEST_COLOURS = {"green": ("#e3f4e8", "#137333"), "amber": ("#fff4d6", "#b06000"),
                     "red": ("#fde7e5", "#b3261e")}


def self_test_json(state):
    safe, ratio, margin, _ = SELF_TEST_STATES[state]
    return load_json(SELF_TEST_JSON % {"safe": safe, "ratio": ratio, "margin": margin, "state": state})


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

SELF_TEST_CSS = """body { font-family: sans-serif; margin: 20px; }
.verdict { border: 4px solid %(border)s; background: %(background)s; color: %(border)s;
  text-align: center; padding: 12px; } .word { font-size: 40pt; font-weight: 800; }
td, th { border: 1px solid #ccc; padding: 2px 6px; } .signature-line { margin-top: 18px; }
h2 { font-size: 13pt; margin: 10px 0 2px; } p { margin: 2px 0; }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 2px 12px; } dd { margin: 0; }
@media print { #page-one { break-after: page; } #result-json { display: none; } }"""


def input_rows(expected, wrong_value):
    """The inputs tables of the self-test's page, grouped by the leaf's path."""
    groups = {}
    for path, text in expected["inputs"]:
        group = {"scene.robot": "robot", "scene.covering": "covering", "scene.head": "human"}.get(
            ".".join(path.split(".")[:2]), "other")
        if wrong_value and path == "scene.robot.mass_kg":
            text = "10"
        key = path.split(".")[-1]
        unit = next((u for suffix, u in (("_kg", "kg"), ("_m_per_s", "m/s"), ("_m", "mm"),
                                         ("_Pa", "MPa")) if key.endswith(suffix)), None)
        if unit is None:
            unit = "-" if re.match(r"^[-0-9.e+]+$", text) else "text"
        source = expected["sources"].get(path, "default")
        groups.setdefault(group, []).append(
            '<tr><td>%s</td><td data-key="%s" data-value="%s">%s</td><td class="unit">%s</td>'
            '<td class="source">%s</td></tr>' % (escape(key.replace("_", " ")), escape(path), escape(text),
                                                 escape(text), unit, escape(source)))
    return "\n".join('<table class="inputs" data-group="%s"><thead><tr><th>quantity</th><th>value</th>'
                     '<th>unit</th><th>source</th></tr></thead><tbody>\n%s\n</tbody></table>'
                     % (group, "\n".join(rows)) for group, rows in groups.items())


def self_test_page(j, state, colour=None, extra="", svg=SELF_TEST_SVG, wrong_value=False, head="",
                   appendix="summary", rows_after=0):
    """A report page in the markup the check expects, from the self-test's JSON; rows_after
    appends that many rows of text after page 1 (a long report)."""
    expected = expectations("simulate", j)
    summary = expected["summary"]
    background, border = SELF_TEST_COLOURS[colour or SELF_TEST_STATES[state][3]]
    word = STATE_WORDS[state]
    margin = float(summary["margin"])
    provenance = j["provenance"]
    page_one = """<section id="page-one"><header><h1>Collision safety report: covopt simulate</h1>
<p>Project: %(project)s · Cell: %(cell)s</p></header>
<section id="verdict" class="verdict" data-state="%(state)s" data-safe="%(safe)s"><div class="word">%(word)s</div>
<p>The governing criterion's margin is <span id="margin" data-value="%(margin_value)s">%(margin)s</span>
against the threshold <span id="margin-threshold" data-value="0.1">10 %%</span>; ratio
<span id="governing-ratio" data-value="%(ratio_value)s">%(ratio).4g</span>.</p></section>
<section id="governing-case"><h2>Governing case</h2><p>head (frontal), contusion, ratio %(ratio).4g, at the peak of the impact</p></section>
<section id="judged"><h2>What was judged</h2><p>head (frontal): laceration, contusion (Park et al. 2011)</p></section>
<section id="covering"><h2>Covering</h2><p>elastomer Shore A60, 15 mm, Hertz law, within its validity</p></section>
<section id="robot"><h2>Robot</h2><p>reflected mass 10 kg, payload 0 kg</p></section>
<section id="sign-off"><h2>Sign-off</h2><dl>
<dt>Project</dt><dd data-field="project">%(project)s</dd><dt>Cell</dt><dd data-field="cell">%(cell)s</dd>
<dt>Assessor</dt><dd data-field="assessor">%(assessor)s</dd><dt>Note</dt><dd data-field="note">%(note)s</dd>
<dt>Date</dt><dd data-field="date">2026-11-26</dd><dt>Version</dt><dd data-field="version">covopt 0.1.0</dd>
<dt>Input digests</dt><dd data-field="digests">s.toml sha256 9f86d081884c7d65…</dd></dl>
<div class="signature-line" data-role="assessor">Assessor: name ________ signature ________ date ________</div>
<div class="signature-line" data-role="approver">Approver: name ________ signature ________ date ________</div>
</section></section>""" % dict(
        {k: escape(v) for k, v in SIGN_OFF.items()}, state=state, safe=SELF_TEST_STATES[state][0],
        word=word, margin_value=summary["margin"].text, margin="%.1f %%" % (100 * margin),
        ratio_value=summary["governing"]["ratio"].text, ratio=float(summary["governing"]["ratio"]))
    long_text = "".join("<p>Row %d of a long report that does not fit its pages.</p>\n" % i
                        for i in range(rows_after))
    return """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">%(head)s
<title>covopt simulate report</title>
<style>%(css)s</style></head>
<body>%(page_one)s
<h2>Inputs</h2>%(inputs)s
<figure class="chart" id="chart-1"><figcaption>force over time</figcaption>%(svg)s</figure>
<section id="appendix" data-appendix="%(appendix)s"><h2>Appendix</h2></section>%(long)s
<details id="result-json"><summary>The result's JSON</summary><pre>%(json)s</pre></details>
<h2>Provenance</h2><p>commit <code>%(commit)s</code></p><p><code>%(command)s</code></p>%(extra)s
</body></html>""" % {"head": head, "css": SELF_TEST_CSS % {"border": border, "background": background},
                     "page_one": page_one, "inputs": input_rows(expected, wrong_value), "svg": svg,
                     "appendix": appendix, "long": long_text,
                     "json": escape(json.dumps({"provenance": provenance})),
                     "commit": escape(provenance["commit"]), "command": escape(provenance["command"]),
                     "extra": extra}


def self_test(browser, scratch):
    """Each check passes a good page and fails a bad one. Returns its failures."""
    failures = []
    csp = ("<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
           "style-src 'unsafe-inline'\">")

    def attempt(name, page, j, want=None, pdf=False, dom=True, in_browser=False, max_pages=4,
                appendix="summary"):
        """Checks the page: its DOM (in the browser, or as written for a markup-only page) and,
        with pdf, Chromium's print of it (its text and page 1's image)."""
        path = os.path.join(scratch, "self-test-%s.html" % name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(page)
        expected = expectations("simulate", j, appendix=appendix)
        found = check_page(browser, path, expected, in_browser) if dom else []
        if pdf:
            pdf_path = path[:-5] + ".pdf"
            code, _, err = browser("--no-pdf-header-footer", "--print-to-pdf=" + pdf_path, file_url(path))
            if code != 0 or not os.path.isfile(pdf_path):
                found.append("chromium --print-to-pdf failed (exit %d): %s" % (code, err[-300:]))
            else:
                found += check_printed(pdf_path, expected, max_pages, path[:-5] + ".png")[0]
        if want is None:
            if found:
                failures.append("self-test %s: a good page failed: %s" % (name, "; ".join(found)))
        elif not any(want in f for f in found):
            failures.append("self-test %s: the check did not catch it (want a failure with %r, got %r)"
                            % (name, want, found))
        else:
            print("self-test %s: caught: %s" % (name, next(f for f in found if want in f)))

    js = {state: self_test_json(state) for state in SELF_TEST_STATES}
    good = {state: self_test_page(js[state], state, head=csp) for state in SELF_TEST_STATES}
    # Good pages, in the browser and printed.
    for state in SELF_TEST_STATES:
        attempt("good-" + state, good[state], js[state], pdf=True, in_browser=True)
    safe, j = good["safe"], js["safe"]
    # The browser: console messages, the printed page 1.
    attempt("console-error", self_test_page(
        j, "safe", extra="<script>console.error('self-test error')</script>"), j, "console: ",
        in_browser=True)
    attempt("csp-violation", self_test_page(j, "safe", head=csp, extra="<script>var x = 1;</script>"),
            j, "console: ", in_browser=True)
    attempt("blank", "<!DOCTYPE html><html><head><meta charset=\"utf-8\"></head><body></body></html>",
            j, "page 1 blank", pdf=True, dom=False)
    attempt("white-text", safe.replace(
        "<body>", "<body style=\"color: white; background: white\"><style>* { color: white !important;"
        " background: white !important; border-color: white !important } svg { display: none }"
        "</style>"), j, "page 1 blank", pdf=True, dom=False)
    attempt("wrong-colour", self_test_page(js["unsafe"], "unsafe", "green", head=csp), js["unsafe"],
            "banner's colour", pdf=True, dom=False)
    attempt("marginal-in-green", self_test_page(js["marginal"], "marginal", "green", head=csp),
            js["marginal"], "banner's colour", pdf=True, dom=False)
    attempt("verdict-after-page-one", safe.replace('<section id="verdict"', '<div style="break-before: page">'
                                                   '</div><section id="verdict"'),
            j, "page 1 of the PDF lacks the state SAFE", pdf=True, dom=False)
    attempt("sign-off-after-page-one", safe.replace('<section id="sign-off"', '<div style="break-before: '
                                                    'page"></div><section id="sign-off"'),
            j, "page 1 of the PDF lacks the word 'Approver'", pdf=True, dom=False)
    attempt("too-many-pages", self_test_page(j, "safe", head=csp, rows_after=400), j,
            "the PDF has", pdf=True, dom=False)
    no_commit = self_test_json("safe")
    no_commit["provenance"]["commit"] = "fedcba9876543210fedcba9876543210fedcba98"
    attempt("pdf-without-commit", safe, no_commit, "the PDF's text lacks the commit", pdf=True, dom=False)
    # The markup, as written (the browser's DOM of these is the same tree).
    marginal_at_safe = self_test_json("marginal")
    marginal_at_safe["summary"]["state"] = "safe"
    breaks = [
        ("wrong-value", self_test_page(j, "safe", wrong_value=True), j, "input scene.robot.mass_kg='10.0'"),
        ("wrong-state", self_test_page(js["marginal"], "marginal").replace(
            'data-state="marginal"', 'data-state="safe"'), js["marginal"], "#verdict data-state='safe'"),
        ("wrong-word", self_test_page(js["marginal"], "marginal").replace(
            '<div class="word">MARGINAL', '<div class="word">SAFE'), js["marginal"], "not the one word MARGINAL"),
        ("no-sentence", safe.replace("The governing criterion's margin is", "").replace(
            "against the threshold", "").replace("; ratio", ""), j, "no sentence"),
        ("summary-state-at-threshold", good["marginal"], marginal_at_safe, "the summary's state 'safe' is not"),
        ("wrong-margin", safe.replace('data-value="0.281789097666724"', 'data-value="0.28"'), j,
         "#margin data-value='0.28'"),
        ("margin-shown-wrong", safe.replace(">28.2 %<", ">2.8 %<"), j, "#margin shows"),
        ("wrong-threshold", safe.replace('data-value="0.1">10 %', 'data-value="0.2">20 %'), j,
         "#margin-threshold data-value='0.2'"),
        ("wrong-ratio", safe.replace('data-value="0.718210902333276"', 'data-value="0.7182"'), j,
         "#governing-ratio data-value='0.7182'"),
        ("no-page-one", safe.replace('id="page-one"', 'id="first-page"'), j, 'elements with id="page-one"'),
        ("sign-off-outside", safe.replace('<section id="sign-off">', '</section><section id="sign-off">')
         .replace("</section></section>", "</section>"), j, "#sign-off is not on page one"),
        ("out-of-order", safe.replace('<section id="judged">', '<section id="judged-later">').replace(
            '<section id="robot">', '<section id="judged"><p>head (frontal) Park et al. 2011</p></section>'
            '<section id="robot">'), j, "is out of order on page one"),
        ("governing-case-target", safe.replace("<p>head (frontal), contusion, ratio", "<p>contusion, ratio"),
         j, "#governing-case lacks the governing target"),
        ("judged-standard", safe.replace("(Park et al. 2011)", ""), j, "#judged lacks the standard"),
        ("covering-thickness", safe.replace("elastomer Shore A60, 15 mm", "elastomer Shore A60, 0.015 m"),
         j, "#covering does not show the thickness"),
        ("sign-off-project", safe.replace('<dd data-field="project">' + escape(SIGN_OFF["project"]),
                                          '<dd data-field="project">'), j, "#sign-off project is"),
        ("sign-off-assessor", safe.replace('data-field="assessor"', 'data-field="assessed-by"'), j,
         '<dd data-field="assessor">'),
        ("sign-off-digests", safe.replace("9f86d081884c7d65…", ""), j, "#sign-off digests lack"),
        ("one-signature-line", safe.replace('<div class="signature-line" data-role="approver">',
                                            '<div data-role="approver">'), j, "signature lines ['assessor']"),
        ("no-unit-header", safe.replace("<th>unit</th>", ""), j, "header"),
        ("empty-unit", safe.replace('<td class="unit">kg</td>', '<td class="unit"></td>', 1), j, "no unit"),
        ("no-source", safe.replace('<td class="source">default</td>', '<td>default</td>', 1), j, "no source"),
        ("wrong-source", safe.replace(">flag --speed<", ">default<"), j,
         "input scene.robot.speed_m_per_s: source"),
        ("bad-group", safe.replace('data-group="human"', 'data-group="head"'), j, "data-group='head'"),
        ("input-outside-tables", safe.replace('<td data-key="scene.head.mass_kg"', '<td data-kee="x"')
         .replace("</pre>", '<span data-key="scene.head.mass_kg" data-value="4.5"></span></pre>'), j,
         "input scene.head.mass_kg='4.5': not in an inputs table"),
        ("json-open", safe.replace('<details id="result-json">', '<details id="result-json" open>'), j,
         "#result-json is an open"),
        ("no-json", safe.replace('id="result-json"', 'id="json"'), j, 'elements with id="result-json"'),
        ("wrong-appendix", safe.replace('data-appendix="summary"', 'data-appendix="full"'), j,
         "#appendix data-appendix='full'"),
        ("no-chart", safe.replace('<figure class="chart" id="chart-1">', '<figure>'), j,
         '0 <figure class="chart">'),
        ("svg-no-namespace", self_test_page(j, "safe", svg=SELF_TEST_SVG.replace(
            ' xmlns="http://www.w3.org/2000/svg"', "")), j, "not in the SVG namespace"),
        ("svg-not-xml", self_test_page(j, "safe", svg=SELF_TEST_SVG.replace("time [ms]", "time&nbsp;[ms]")),
         j, "is not XML"),
    ]
    for name in PAGE_ONE_SECTIONS + ("margin", "margin-threshold", "governing-ratio", "appendix"):
        breaks.append(("no-" + name, safe.replace('id="%s"' % name, 'id="%s-renamed"' % name), j,
                       '0 elements with id="%s"' % name))
    for name, page, page_json, want in breaks:
        attempt(name, page, page_json, want)
    attempt("good-markup-appendix-none", self_test_page(j, "safe", appendix="none"), j, appendix="none")
    return failures


# --- the covopt runs ------------------------------------------------------------------------------


def sign_off_flags(info):
    return [a for field, value in info.items() for a in ("--" + field, value)]


def cases(root):
    urdf = os.path.join(root, "robot/models/franka_fr3.urdf")
    pick = os.path.join(root, "robot/models/franka_fr3_pick.csv")
    robot = ["--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick]
    # A compressible covering (ν 0.3): a solid elastomer (ν >= 0.45) would leave its law at 20 % strain.
    audit = robot + ["--covering-modulus", "0.5MPa", "--covering-poisson", "0.3",
                     "--contact-area", "1cm2", "--flat-face-radius", "20mm"]
    retime = audit + ["--covering-thickness", "10mm", "--surface-spacing", "100mm", "--joint-accel-limit", "10"]
    speed_limit = ["speed-limit", "--material", "elastomer Shore A60", "--covering-thickness", "20mm"]
    # (name, kind, arguments, state, margin threshold, most pages of the PDF). optimize's default
    # answer has a margin of 0.2 %: MARGINAL at the default 10 %, SAFE at 0.1 %. speed-limit is
    # a table of limits (LIMITS); it has no UNSAFE report within reach: a row without a safe
    # value needs even 1e-6 m/s (or a vanishing mass) to be unsafe, which the head model never
    # finds (every ratio vanishes with the speed).
    runs = [
        ("simulate-safe", "simulate", ["simulate", "--speed", "1m/s"], "safe", 0.1, PDF_MAX_PAGES),
        ("simulate-unsafe", "simulate", ["simulate", "--speed", "2m/s"], "unsafe", 0.1, PDF_MAX_PAGES),
        ("simulate-body-regions", "simulate", ["simulate", "--body-region", "all"], None, 0.1,
         PDF_MAX_PAGES),
        ("optimize-marginal", "optimize", ["optimize"], "marginal", 0.1, 4),
        ("optimize-safe", "optimize", ["optimize"], "safe", 0.001, 4),
        ("optimize-unsafe", "optimize", ["optimize", "--max-thickness", "3mm"], "unsafe", 0.1, 4),
        ("speed-limit", "speed-limit", speed_limit + ["--robot-mass", "1kg,5kg,20kg"], "limits", 0.1, 4),
        ("speed-limit-chest", "speed-limit", speed_limit + ["--body-region", "chest"], "limits", 0.1, 4),
        ("trajectory-safe", "robot --trajectory", ["robot"] + robot, "safe", 0.1, PDF_MAX_PAGES),
        ("trajectory-unsafe", "robot --trajectory", ["robot"] + robot + ["--covering-thickness", "1mm"],
         "unsafe", 0.1, PDF_MAX_PAGES),
        ("audit-safe", "audit", ["audit"] + audit + ["--covering-thickness", "40mm"], "safe", 0.1, 8),
        ("audit-unsafe", "audit", ["audit"] + audit + ["--covering-thickness", "10mm"], "unsafe", 0.1, 8),
        # A time-optimal timing touches its limit: MARGINAL (margin about 0) at the default threshold.
        ("retime-marginal", "retime", ["retime"] + retime + ["--thickness", "5mm,20mm"], "marginal", 0.1, 8),
    ]
    # Bad input, one per kind: exit 2 and no report.
    bad = [
        ["simulate", "--speed", "-1m/s"],
        ["optimize", "--max-thickness", "-3mm"],
        ["speed-limit", "--robot-mass", "-1kg"],
        ["robot"] + robot + ["--covering-thickness", "-1mm"],
        ["audit"] + audit + ["--covering-thickness", "-1mm"],
        ["retime"] + retime[:-2] + ["--joint-accel-limit", "-10"],
    ]
    return runs, bad


# The cases whose PDF is also printed with --report-appendix none and full, and the kind each
# one's page 1 pictures in the guide (docs/images/report-<kind>.png).
APPENDIX_CASES = ("optimize-marginal", "audit-safe")
DOCS_CASES = {"simulate-safe": "simulate", "optimize-marginal": "optimize", "speed-limit": "speed-limit",
              "trajectory-safe": "trajectory", "audit-unsafe": "audit",
              "simulate-body-regions": "body-regions", "retime-marginal": "retime"}


def run_covopt(covopt, arguments, env=None):
    return run([covopt] + arguments, COVOPT_TIMEOUT_S, env)


def report_flags(threshold, appendix="summary"):
    flags = sign_off_flags(SIGN_OFF) + ["--report-appendix", appendix]
    return flags + (["--margin-threshold", "%g" % threshold] if threshold != 0.1 else [])


def check_case(covopt, browser, scratch, case, report):
    """One case: the HTML report in the browser, the PDF, and with APPENDIX_CASES the PDF with
    the other appendices. Returns the failures and the PDF's page 1 as a PNG."""
    name, kind, arguments, state, threshold, max_pages = case
    failures = []
    html_path = os.path.join(scratch, name + ".html")
    code, out, err = run_covopt(covopt, arguments + report_flags(threshold) + ["--json", "--report", html_path])
    if code not in (0, 1) or not os.path.isfile(html_path):
        return ["%s: covopt %s --json --report x.html: exit %d, %s" %
                (name, " ".join(arguments), code, err.strip()[-500:])], None
    expected = expectations(kind, load_json(out), threshold)
    if state is not None and expected["state"] != state:
        failures.append("%s: the case is meant to be %s, the summary says %s"
                        % (name, STATE_WORDS[state], STATE_WORDS.get(expected["state"], expected["state"])))
    failures += ["%s: %s" % (name, f) for f in check_page(browser, html_path, expected)]
    report["cases"][name] = {"kind": kind, "state": expected["state"], "ratio": expected["ratio"],
                             "margin": expected["margin"], "inputs": len(expected["inputs"])}
    pages = {}
    png = None
    for appendix in ("summary",) + (("none", "full") if name in APPENDIX_CASES else ()):
        pdf = os.path.join(scratch, "%s-%s.pdf" % (name, appendix))
        code, out, err = run_covopt(covopt, arguments + report_flags(threshold, appendix) +
                                    ["--json", "--report", pdf])
        if code not in (0, 1) or not os.path.isfile(pdf):
            failures.append("%s: covopt --report x.pdf --report-appendix %s: exit %d, %s"
                            % (name, appendix, code, err.strip()[-500:]))
            continue
        if appendix != "summary":
            pages[appendix] = pdf_pages(pdf)
            continue
        pdf_expected = expectations(kind, load_json(out), threshold)
        for key in ("margin_shown", "governing_ratio_shown"):
            pdf_expected[key] = expected.get(key, "")
        png = os.path.join(scratch, name + "-page-1.png")
        pdf_failures, pages["summary"], stats = check_printed(pdf, pdf_expected, max_pages, png)
        failures += ["%s: %s" % (name, f) for f in pdf_failures]
        report["cases"][name]["page_1"] = stats
    if len(pages) == 3 and not pages["none"] <= pages["summary"] < pages["full"]:
        failures.append("%s: pages with --report-appendix none %d, summary %d, full %d (want none <= "
                        "summary < full)" % (name, pages["none"], pages["summary"], pages["full"]))
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
    link = os.path.join(bin_dir, "gnuplot")
    if gnuplot and not os.path.lexists(link):  # the charts still need gnuplot (--keep reuses the folder)
        os.symlink(gnuplot, link)
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
                        help="also write page 1 of each kind to REPO_ROOT/docs/images/report-<kind>.png")
    parser.add_argument("--keep", metavar="DIR", help="write the reports, PDFs and images here")
    args = parser.parse_args()
    if not args.self_test and not args.covopt:
        parser.error("--covopt is required (or --self-test)")

    missing = []
    chromium = find_chromium()
    if chromium is None:
        missing.append("chromium (Debian package chromium)")
    for tool in ("pdftotext", "pdfinfo", "pdftoppm"):
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
        print("check_reports: self-test %.1f s" % (time.monotonic() - start))
        if not args.self_test:
            covopt = os.path.abspath(args.covopt)
            root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
            runs, bad_runs = cases(root)
            for case in runs:
                try:
                    case_failures, png = check_case(covopt, browser, scratch, case, report)
                except (CheckFailed, KeyError, TypeError, ValueError) as e:  # a JSON not as expected
                    case_failures, png = ["%s: %s: %s" % (case[0], type(e).__name__, e)], None
                failures += case_failures
                if args.update_docs and case[0] in DOCS_CASES and png:
                    pdf = os.path.join(scratch, "%s-summary.pdf" % case[0])
                    write_docs_image(pdf, DOCS_CASES[case[0]], args.update_docs, scratch)
            failures += check_failed_runs(covopt, scratch, bad_runs)
            failures += check_without_browser(covopt, scratch, runs[0][2])
    except CheckFailed as e:
        failures.append(str(e))
    finally:
        if not args.keep:
            shutil.rmtree(scratch, ignore_errors=True)
    for name, case in report["cases"].items():
        stats = case.get("page_1") or {}
        print("%-22s %-8s ratio %-10s margin %-10s inputs %4d  page 1: non-white %.3f, %6d colours, "
              "deviation %5.1f, banner %s; PDF pages %s"
              % (name, STATE_WORDS.get(case["state"], case["state"]), "%.4g" % case["ratio"]
                 if case["ratio"] is not None else "null",
                 "%.4g" % case["margin"] if isinstance(case["margin"], float) else "null", case["inputs"],
                 stats.get("non_white_share", 0), stats.get("distinct_colours", 0),
                 stats.get("luminance_stddev", 0), stats.get("banner"), case.get("pdf_pages")))
    print("check_reports: %d browser runs, %.1f s" % (browser.runs, time.monotonic() - start))
    if failures:
        print("check_reports: FAILED:\n  " + "\n  ".join(failures), file=sys.stderr)
        return 1
    print("check_reports: all checks passed")
    return 0


def write_docs_image(pdf, kind, repo_root, scratch):
    """Page 1 of the kind's PDF for the guide, as a small PNG (a palette of 64 colours)."""
    target = os.path.join(repo_root, "docs", "images", "report-%s.png" % kind)
    os.makedirs(os.path.dirname(target), exist_ok=True)
    png = page_image(pdf, os.path.join(scratch, "docs-%s.png" % kind), DOCS_IMAGE_DPI)
    image = Image.open(png).convert("RGB").quantize(colors=64)
    image.save(target, optimize=True)
    print("check_reports: wrote %s (%d bytes)" % (target, os.path.getsize(target)))


if __name__ == "__main__":
    sys.exit(main())
