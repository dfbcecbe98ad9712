#!/usr/bin/env python3
"""Re-runs every shown output of README.md and docs/guide/*.md, and every marked worked number of
docs/model.md, and writes them back.

A shown output is a ```text block whose first line is a command:

    ```text
    $ ./build/cli/covopt simulate --speed 1m/s
    ...what the command prints (stdout, then stderr)...
    [exit 2]                      <- only when the exit status is not 0
    ```

- A block may hold several commands; each line starting with "$ " starts one, and a command
  continues onto the next line when its line ends with a backslash. Pipes (`| head -n 12`)
  and anything else bash understands are allowed.
- A command runs with bash in a scratch directory that links every top-level entry of the
  repository (so `robot/models/...`, `docs/...` and `cli/examples/...` resolve, and the files a
  command writes, `--csv map.csv`, land in the scratch directory, not in the tree), with
  `build` linked to the build directory given by --build (default: the repository's build/).
- The output shown is stdout followed by stderr, trailing blanks removed, and a last line
  `[exit N]` when the command exits with N != 0.
- A block whose first command is `$ PYTHONPATH=build/python /usr/bin/python3` is a Python
  session: each `>>> ` line (with `... ` continuation lines) is run as the interactive
  interpreter runs it, its value or printed text shown below it; an exception is shown as its
  one-line `Name: message` (module-qualified when not a builtin).

A command fails unexpectedly when its exit status differs from the `[exit N]` the block shows
(none shown = 0), or when a Python statement raises where the block showed no exception. Such a
block is left as it is and the script exits 1, naming it.

--check writes nothing: it reports every block whose output differs from what the binary prints
now, and exits 1 if any does. Wall times (a number followed by s, ms or µs, the workprecision
table's µs/impact column, JSON "seconds") are masked before comparing, since they differ from
run to run. Every command and Python session runs with SOURCE_DATE_EPOCH=1700000000, so the
provenance block of a JSON (docs/guide/output-files.md) shows a fixed date; its "commit" (the
build's, which changes with every commit) is masked before comparing too.

Worked numbers in prose and tables (docs/model.md) are a second kind: a number followed by a
marker `<!-- value: NAME -->` (invisible when rendered), and somewhere in the same file a
definition block

    <!-- regen-docs values
    $ ./build/cli/covopt simulate --covering-thickness 0 --json
    bare-dmax-mm: "max_penetration_m": ([0-9.e+-]+) | mm 7
    -->

Each `$ ` line is a command (run as a block's, in the scratch directory; it must exit 0); each
`NAME: REGEX` line after it defines a value from that command's output: the first match of
REGEX (Python, multiline), its group 1; `json:KEY` stands for the REGEX `"KEY": (number)`, the
first such key of a --json output. An optional `| UNIT DIGITS` converts an SI value (m to mm,
s to ms, Pa to MPa or kPa, anything else as it is with x1) and prints it with DIGITS
significant digits, trailing zeros kept, and `| UNIT DIGITS group` groups the integer part's
thousands with a space from five digits on (54 593.88, 3310.561); without it the matched text is the value as shown. Every marked number is replaced by its value (--check: compared with it);
a marker naming no definition, a definition that matches nothing and a command that fails are
errors. The default files include docs/model.md for these values (it has no command blocks).

Usage: scripts/regen-docs.py [--check] [--build DIR] [--verbose] [FILE.md ...]
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
COVOPT_PREFIX = "$ ./build/cli/covopt"
PYTHON_PREFIX = "$ PYTHONPATH=build/python /usr/bin/python3"
EXIT_LINE = re.compile(r"^\[exit (\d+)\]$")
COMMAND_TIMEOUT_S = 120
# Reproducible provenance blocks: the date (covopt/report/provenance.hpp reads it).
FIXED_ENV = {"SOURCE_DATE_EPOCH": "1700000000"}

# The interactive interpreter, emulated: statements come on stdin separated by a marker line;
# each statement's output (the value's repr, anything printed, or `Name: message`) is printed
# after a marker line of its own.
PYTHON_SESSION = r'''
import sys, traceback
SEP = "\x00STATEMENT\x00"
chunks = sys.stdin.read().split(SEP + "\n")[1:]
env = {"__name__": "__main__"}
sys.stderr = sys.stdout
for chunk in chunks:
    print(SEP, flush=True)
    try:
        code = compile(chunk, "<stdin>", "single")
        exec(code, env)
    except SystemExit:
        raise
    except BaseException as e:
        t = type(e)
        name = t.__qualname__ if t.__module__ == "builtins" else t.__module__ + "." + t.__qualname__
        print("\x00RAISED\x00" + (name + ": " + str(e) if str(e) else name))
    sys.stdout.flush()
'''
STATEMENT_MARK = "\x00STATEMENT\x00"
RAISED_MARK = "\x00RAISED\x00"


@dataclass
class Block:
    path: Path
    start: int  # index of the first line after ```text
    end: int  # index of the closing ```
    lines: list[str]
    line_number: int = 0  # 1-based, of the ```text line

    def where(self) -> str:
        return f"{self.path.relative_to(REPO)}:{self.line_number}"


@dataclass
class Outcome:
    new_lines: list[str] | None = None
    problems: list[str] = field(default_factory=list)


def find_blocks(path: Path, lines: list[str]) -> list[Block]:
    blocks = []
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```text":
            j = i + 1
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            body = lines[i + 1 : j]
            if body and (body[0].startswith(COVOPT_PREFIX) or body[0].rstrip() == PYTHON_PREFIX):
                blocks.append(Block(path, i + 1, j, body, i + 1))
            i = j + 1
        else:
            i += 1
    return blocks


def split_entries(lines: list[str], prompt: str, continues) -> list[tuple[list[str], list[str]]]:
    """[(input lines as shown, output lines as shown)]: each input starts with `prompt` and goes
    on while continues(previous line, next line); its output runs to the next prompt."""
    entries = []
    i = 0
    while i < len(lines):
        if not lines[i].startswith(prompt):
            raise ValueError(f"expected a line starting with {prompt!r}, got {lines[i]!r}")
        head = [lines[i]]
        i += 1
        while i < len(lines) and continues(head[-1], lines[i]):
            head.append(lines[i])
            i += 1
        out = []
        while i < len(lines) and not lines[i].startswith(prompt):
            out.append(lines[i])
            i += 1
        entries.append((head, out))
    return entries


def split_commands(lines: list[str]) -> list[tuple[list[str], list[str]]]:
    """A shell block's commands: "$ " lines, continued by a trailing backslash."""
    return split_entries(lines, "$ ", lambda previous, _: previous.endswith("\\"))


def shown_exit(out: list[str]) -> int:
    if out:
        m = EXIT_LINE.match(out[-1])
        if m:
            return int(m.group(1))
    return 0


def clean(text: str) -> list[str]:
    lines = [line.rstrip() for line in text.replace("\r\n", "\n").split("\n")]
    while lines and not lines[-1]:
        lines.pop()
    return lines


def make_scratch(build: Path) -> Path:
    scratch = Path(tempfile.mkdtemp(prefix="covopt-regen-docs-"))
    for entry in REPO.iterdir():
        if entry.name in ("build", ".git"):
            continue
        (scratch / entry.name).symlink_to(entry)
    (scratch / "build").symlink_to(build)
    return scratch


def run_shell(block: Block, scratch: Path, verbose: bool) -> Outcome:
    outcome = Outcome()
    new = []
    for cmd, old_out in split_commands(block.lines):
        text = "\n".join(cmd)[2:]
        start = time.monotonic()
        try:
            proc = subprocess.run(["bash", "-c", text], cwd=scratch, capture_output=True,
                                  timeout=COMMAND_TIMEOUT_S, env=dict(os.environ, **FIXED_ENV))
        except subprocess.TimeoutExpired:
            outcome.problems.append(f"{block.where()}: '{cmd[0]}' ran over {COMMAND_TIMEOUT_S} s")
            return outcome
        if verbose:
            print(f"  {time.monotonic() - start:6.2f} s  {cmd[0]}", file=sys.stderr)
        out = clean(proc.stdout.decode("utf-8", "replace") + proc.stderr.decode("utf-8", "replace"))
        if proc.returncode != 0:
            out.append(f"[exit {proc.returncode}]")
        expected = shown_exit(old_out)
        if proc.returncode != expected:
            tail = "\n    ".join(out[-5:])
            outcome.problems.append(
                f"{block.where()}: '{cmd[0]}' exited {proc.returncode}, the block shows {expected}:\n    {tail}")
        new += cmd + out
    if not outcome.problems:
        outcome.new_lines = new
    return outcome


def split_session(lines: list[str]) -> list[tuple[list[str], list[str]]]:
    """A Python block's statements (after its $ line): ">>> " lines, continued by "... " lines."""
    return split_entries(lines, ">>> ", lambda _, line: line.startswith("... "))


def looks_raised(out: list[str]) -> bool:
    return bool(out) and re.match(r"^[A-Za-z_][\w.]*(Error|Exception|Warning)\b", out[0]) is not None


def run_python(block: Block, scratch: Path, verbose: bool) -> Outcome:
    outcome = Outcome()
    statements = split_session(block.lines[1:])
    source = "".join(f"{STATEMENT_MARK}\n" + "\n".join(line[4:] for line in stmt) + "\n"
                     for stmt, _ in statements)
    env = dict(os.environ, PYTHONPATH=str(scratch / "build" / "python"), **FIXED_ENV)
    start = time.monotonic()
    try:
        proc = subprocess.run(["/usr/bin/python3", "-c", PYTHON_SESSION], cwd=scratch, input=source.encode(),
                              capture_output=True, timeout=COMMAND_TIMEOUT_S, env=env)
    except subprocess.TimeoutExpired:
        outcome.problems.append(f"{block.where()}: the Python session ran over {COMMAND_TIMEOUT_S} s")
        return outcome
    if verbose:
        print(f"  {time.monotonic() - start:6.2f} s  {block.lines[0]}", file=sys.stderr)
    text = proc.stdout.decode("utf-8", "replace")
    pieces = text.split(STATEMENT_MARK + "\n")[1:]
    if proc.returncode != 0 or len(pieces) != len(statements):
        outcome.problems.append(f"{block.where()}: the Python session failed (exit {proc.returncode}):\n    "
                                + proc.stderr.decode("utf-8", "replace").strip().replace("\n", "\n    "))
        return outcome
    new = [block.lines[0]]
    for (stmt, old_out), piece in zip(statements, pieces):
        raised = RAISED_MARK in piece
        out = clean(piece.replace(RAISED_MARK, ""))
        if raised and not looks_raised(old_out):
            outcome.problems.append(f"{block.where()}: '{stmt[0]}' raised where the block shows no exception:\n    "
                                    + "\n    ".join(out))
        new += stmt + out
    if not outcome.problems:
        outcome.new_lines = new
    return outcome


TIME_TOKEN = re.compile(r"\d+(\.\d+)?(e[-+]?\d+)? ?(ms|s|µs)\b")
JSON_SECONDS = re.compile(r'("seconds": )[0-9.e+-]+')
JSON_COMMIT = re.compile(r'("commit": ")[0-9a-f]{40}(-dirty)?(")')
WORKPRECISION_TIME = re.compile(r"\s+\d+\.\d\d(?=\s)")  # the µs/impact column, with its padding


def masked(lines: list[str]) -> list[str]:
    """The lines with the wall times replaced by '#', for --check."""
    out = []
    in_workprecision = False
    for line in lines:
        if line.startswith("$ "):
            in_workprecision = " workprecision" in line
        else:
            line = TIME_TOKEN.sub("# s", line)
            line = JSON_SECONDS.sub(r"\1#", line)
            line = JSON_COMMIT.sub(r"\1#\3", line)
            if in_workprecision:
                line = WORKPRECISION_TIME.sub(" #", line)  # a wider time shifts no column
        out.append(line)
    return out


VALUE_BLOCK = "<!-- regen-docs values"
VALUE_MARKER = re.compile(r"([+-]?(?:\d{1,3}(?: \d{3})+(?:\.\d+)?|\d[\d.]*(?:e[+-]?\d+)?))<!-- value: ([\w.-]+) -->")
VALUE_DEFINITION = re.compile(r"^([\w.-]+): (.*?)(?: \| (mm|ms|MPa|kPa|x1) (\d+)( group)?)?$")
JSON_NUMBER = r'"{}": ([-+0-9.eE]+)'
SI_SCALE = {"mm": 1e3, "ms": 1e3, "MPa": 1e-6, "kPa": 1e-3, "x1": 1.0}


def format_value(text: str, unit: str | None, digits: str | None, group: bool = False) -> str:
    """The value as the document shows it: the matched text, or an SI number scaled to `unit`
    with `digits` significant digits (trailing zeros kept), thousands grouped with `group`."""
    if unit is None:
        return text
    value = float(text) * SI_SCALE[unit]
    shown = f"{value:#.{int(digits)}g}"
    shown = shown[:-1] if shown.endswith(".") else shown
    if "e" in shown:  # 6e-8, as prose writes it, not 6.e-08
        mantissa, _, exponent = shown.partition("e")
        shown = mantissa.rstrip(".") + "e" + str(int(exponent))
    elif group:
        whole, dot, fraction = shown.partition(".")
        sign = whole[0] if whole[0] in "+-" else ""
        whole = whole[len(sign):]
        groups = []
        while len(whole) > 3 and len(whole) + 3 * len(groups) > 4:  # 4 digits stay whole (3310.561)
            groups.insert(0, whole[-3:])
            whole = whole[:-3]
        shown = sign + " ".join([whole] + groups) + dot + fraction
    return shown


def regen_values(path: Path, lines: list[str], scratch: Path, check: bool,
                 verbose: bool) -> tuple[list[str], list[str], int]:
    """The marked worked numbers of `path` (see the module comment): replaced in `lines` by the
    values the binary prints now, or with `check` compared. Returns (drift, problems, commands run)."""
    problems: list[str] = []
    definitions: dict[str, tuple[str, str, str | None, str | None, bool, int]] = {}
    i = 0
    while i < len(lines):
        if lines[i].strip() != VALUE_BLOCK:
            i += 1
            continue
        command = None
        i += 1
        while i < len(lines) and lines[i].strip() != "-->":
            line = lines[i].rstrip()
            if line.startswith("$ "):
                command = line[2:]
                while command.endswith("\\") and i + 1 < len(lines):
                    i += 1
                    command = command[:-1] + "\n" + lines[i].rstrip()
            elif line.strip():
                m = VALUE_DEFINITION.match(line.strip())
                if not m or command is None:
                    problems.append(f"{path.relative_to(REPO)}:{i + 1}: not a value definition (NAME: REGEX [| UNIT DIGITS]) after a $ command: {line!r}")
                else:
                    pattern = m.group(2)
                    if pattern.startswith("json:"):
                        pattern = JSON_NUMBER.format(re.escape(pattern[5:]))
                    definitions[m.group(1)] = (command, pattern, m.group(3), m.group(4), bool(m.group(5)), i + 1)
            i += 1
        i += 1
    used = {m.group(2) for line in lines for m in VALUE_MARKER.finditer(line)}
    if not used and not definitions:
        return [], problems, 0
    outputs: dict[str, str | None] = {}
    for command in dict.fromkeys(d[0] for d in definitions.values()):
        start = time.monotonic()
        try:
            proc = subprocess.run(["bash", "-c", command], cwd=scratch, capture_output=True,
                                  timeout=COMMAND_TIMEOUT_S, env=dict(os.environ, **FIXED_ENV))
        except subprocess.TimeoutExpired:
            problems.append(f"{path.relative_to(REPO)}: '{command}' ran over {COMMAND_TIMEOUT_S} s")
            outputs[command] = None
            continue
        if verbose:
            print(f"  {time.monotonic() - start:6.2f} s  $ {command}", file=sys.stderr)
        text = proc.stdout.decode("utf-8", "replace") + proc.stderr.decode("utf-8", "replace")
        if proc.returncode != 0:
            problems.append(f"{path.relative_to(REPO)}: '{command}' exited {proc.returncode}:\n    "
                            + "\n    ".join(clean(text)[-5:]))
            outputs[command] = None
        else:
            outputs[command] = text
    values: dict[str, str] = {}
    for name, (command, pattern, unit, digits, group, line_number) in definitions.items():
        if outputs.get(command) is None:
            continue
        m = re.search(pattern, outputs[command], re.MULTILINE)
        if not m:
            problems.append(f"{path.relative_to(REPO)}:{line_number}: value {name}: /{pattern}/ matches nothing in the output of '{command}'")
            continue
        values[name] = format_value(m.group(1), unit, digits, group)
    for name in sorted(used - set(definitions)):
        problems.append(f"{path.relative_to(REPO)}: a number is marked '{name}', which no regen-docs values block defines")
    drift: list[str] = []
    for k, line in enumerate(lines):
        def replace(m: re.Match) -> str:
            name = m.group(2)
            if name not in values:
                return m.group(0)
            if values[name] != m.group(1):
                drift.append(f"{path.relative_to(REPO)}:{k + 1}: {name} shows {m.group(1)}, the binary gives {values[name]}")
            return values[name] + m.group(0)[len(m.group(1)):]
        new = VALUE_MARKER.sub(replace, line)
        if not check:
            lines[k] = new
    return (drift if check else []), problems, len(outputs)


def diff(old: list[str], new: list[str]) -> str:
    import difflib
    return "\n".join(difflib.unified_diff(old, new, "shown", "now", lineterm="", n=1))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="report drift, write nothing")
    parser.add_argument("--build", type=Path, default=REPO / "build",
                        help="build directory with cli/covopt and python/ (default: build)")
    parser.add_argument("--verbose", "-v", action="store_true", help="time each command")
    parser.add_argument("files", nargs="*", type=Path)
    args = parser.parse_args()

    build = args.build.resolve()
    if not os.access(build / "cli" / "covopt", os.X_OK):
        print(f"regen-docs: no binary at {build / 'cli' / 'covopt'}; build first or give --build", file=sys.stderr)
        return 2
    files = [f.resolve() for f in args.files] or [REPO / "README.md", *sorted((REPO / "docs" / "guide").glob("*.md")),
                                                   REPO / "docs" / "model.md"]

    scratch = make_scratch(build)
    problems: list[str] = []
    drifted: list[str] = []
    blocks_run = 0
    start = time.monotonic()
    try:
        for path in files:
            lines = path.read_text(encoding="utf-8").split("\n")
            blocks = find_blocks(path, lines)
            file_drift: list[str] = []
            if args.verbose and blocks:
                print(f"{path.relative_to(REPO)}: {len(blocks)} blocks", file=sys.stderr)
            for block in reversed(blocks):  # from the end, so earlier indices stay valid
                runner = run_python if block.lines[0].rstrip() == PYTHON_PREFIX else run_shell
                try:
                    outcome = runner(block, scratch, args.verbose)
                except ValueError as e:
                    problems.append(f"{block.where()}: {e}")
                    continue
                blocks_run += 1
                problems += outcome.problems
                if outcome.new_lines is None:
                    continue
                if args.check:
                    if masked(outcome.new_lines) != masked(block.lines):
                        file_drift.append(f"{block.where()}:\n{diff(block.lines, outcome.new_lines)}")
                else:
                    lines[block.start:block.end] = outcome.new_lines
            drifted += reversed(file_drift)
            value_drift, value_problems, values_run = regen_values(path, lines, scratch, args.check, args.verbose)
            drifted += value_drift
            problems += value_problems
            blocks_run += values_run
            if not args.check:
                text = "\n".join(lines)
                if text != path.read_text(encoding="utf-8"):
                    path.write_text(text, encoding="utf-8")
                    print(f"regen-docs: updated {path.relative_to(REPO)}", file=sys.stderr)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)

    for d in drifted:
        print(f"drift: {d}\n")
    for p in problems:
        print(f"regen-docs: {p}", file=sys.stderr)
    seconds = time.monotonic() - start
    print(f"regen-docs: {blocks_run} blocks in {len(files)} files, {len(drifted)} drifted, "
          f"{len(problems)} failed, {seconds:.1f} s", file=sys.stderr)
    return 1 if problems or drifted else 0


if __name__ == "__main__":
    sys.exit(main())
