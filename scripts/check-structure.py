#!/usr/bin/env python3
"""The structure rules of issue 34's "Done when", checked over the repository's source.

The source: every C++ (.cpp .cc .cxx .hpp .hh .h .ipp) and Python (.py) file of the repository
(`git ls-files` when the tree is a git checkout, else a walk of the tree) that ships as the
library, the CLI or the module: not under the top-level tests/, bench/, fuzz/, scripts/ (the
project's own tools) or docs/ (the validation scripts), not in any folder named tests, examples
(python/examples) or __pycache__, and not in a build tree (a top-level folder whose name starts
with "build", or any folder holding a CMakeCache.txt).

The checks (each prints every offender as path:line: name (length) and a summary line):
  functions  no function over 100 lines. C++: a function body found by a brace-matching scan of
             the code with its comments, string, character and raw-string literals and
             preprocessor lines blanked; its length counts from the line the signature starts on
             (its template line included) to the line of the closing brace; a lambda counts
             inside its enclosing function (a lambda at namespace scope counts as a function).
             Python: each def, `ast` end_lineno - lineno + 1 (decorators not counted).
  files      no file over 800 lines.
  shells     cli/ + python/ under 25 % of the lines of the source.
  includes   in cli/, a command's files are included by its own files and by the registry
             (app.cpp, main.cpp) only. A command is cli/<stem> whose .cpp registers a subcommand
             (calls add_subcommand) or whose .hpp declares the function that sets one up
             (Setup<Name>(...), called by the registry); its files are cli/<stem>.cpp,
             cli/<stem>.hpp and its parts, the cli/<stem>_<part>.{cpp,hpp} of which one includes
             cli/<stem>.hpp. Any other cli/ file that includes one of them is an offender: a
             command including another command's file, or a shared module reaching up into a
             command (through which commands would include each other).
  rules      no CLI or Python file (cli/, python/ outside tests) writes a rule that the library
             holds: the patterns of RULE_PATTERNS below, matched on the code with comments
             blanked (and string literals blanked, except for the region-name patterns).

Usage: check-structure.py [--root DIR] [--check NAME ...] [--list-sources]
Exit status: 0 when every check passes, 1 when any fails, 2 on bad usage or unreadable input.
"""

from __future__ import annotations

import argparse
import ast
import bisect
import io
import os
import re
import subprocess
import sys
import tokenize
from dataclasses import dataclass
from pathlib import Path

MAX_FUNCTION_LINES = 100
MAX_FILE_LINES = 800
MAX_SHELL_SHARE = 0.25
SHELL_DIRS = ("cli", "python")
CXX_EXTENSIONS = (".cpp", ".cc", ".cxx", ".hpp", ".hh", ".h", ".ipp")
PY_EXTENSIONS = (".py",)
EXCLUDED_TOP = ("tests", "bench", "fuzz", "scripts", "docs")
EXCLUDED_ANYWHERE = ("tests", "examples", "__pycache__", ".git")
REGISTRY_FILES = ("cli/app.cpp", "cli/main.cpp")
CHECKS = ("functions", "files", "shells", "includes", "rules")


# ---- the source list ---------------------------------------------------------------------

def is_counted(rel: str) -> bool:
    """Whether a repository-relative path (forward slashes) is source the rules cover."""
    parts = rel.split("/")
    if not rel.endswith(CXX_EXTENSIONS + PY_EXTENSIONS):
        return False
    if parts[0] in EXCLUDED_TOP or parts[0].startswith("build"):
        return False
    return not any(p in EXCLUDED_ANYWHERE for p in parts[:-1])


def git_files(root: Path) -> list[str] | None:
    if not (root / ".git").exists():
        return None
    try:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    # A deleted but still tracked file is not source.
    return [f for f in out.stdout.decode().split("\0") if f and (root / f).is_file()]


def walked_files(root: Path) -> list[str]:
    files = []
    for dirpath, dirnames, filenames in os.walk(root):
        rel_dir = Path(dirpath).relative_to(root)
        if "CMakeCache.txt" in filenames and rel_dir != Path("."):
            dirnames[:] = []
            continue
        dirnames[:] = sorted(d for d in dirnames if not d.startswith("."))
        files += [(rel_dir / f).as_posix() for f in filenames]
    return files


def source_files(root: Path) -> list[str]:
    files = git_files(root)
    if files is None:
        files = walked_files(root)
    return sorted(f for f in files if is_counted(f))


# ---- C++ lexing: blank comments, literals and preprocessor lines --------------------------

RAW_STRING = re.compile(r'(?:u8|u|U|L)?R"([^ ()\\\t\n]{0,16})\(')
STRING_PREFIX = re.compile(r'(?:u8|u|U|L)$')


def blank_cxx(text: str, keep_strings: bool = False) -> str:
    """The text with comments (and, unless keep_strings, string and character literals)
    replaced by spaces, newlines kept, so offsets and line numbers stay those of the file.
    Preprocessor lines are blanked too (their braces are no code)."""
    out = list(text)
    n = len(text)

    def blank(a: int, b: int) -> None:
        for k in range(a, min(b, n)):
            if out[k] != "\n":
                out[k] = " "

    i = 0
    line_start = True
    while i < n:
        c = text[i]
        if c == "\n":
            line_start = True
            i += 1
            continue
        if line_start and c in " \t":
            i += 1
            continue
        if line_start and c == "#":
            j = i
            while j < n and text[j] != "\n":
                if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n":
                    j += 2
                    continue
                if text.startswith("/*", j):  # a block comment starting on the directive line
                    end = text.find("*/", j + 2)
                    j = n if end < 0 else end + 2
                    continue
                j += 1
            blank(i, j)
            i = j
            continue
        line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            blank(i, j)
            i = j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            blank(i, j)
            i = j
            continue
        if c == '"' or (c == "R" and text.startswith('R"', i)) or (c in "uUL" and RAW_STRING.match(text, i)):
            m = RAW_STRING.match(text, i)
            if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
                close = ")" + m.group(1) + '"'
                j = text.find(close, m.end())
                j = n if j < 0 else j + len(close)
                if not keep_strings:
                    blank(m.end() - 1, j - 1)
                i = j
                continue
            if c == '"':
                j = i + 1
                while j < n and text[j] != '"' and text[j] != "\n":
                    j += 2 if text[j] == "\\" else 1
                if not keep_strings:
                    blank(i + 1, j)
                i = j + 1
                continue
        if c == "'":
            # A digit separator (1'000'000) when the token it is in starts with a digit.
            k = i
            while k > 0 and (text[k - 1].isalnum() or text[k - 1] in "_.'"):
                k -= 1
            if k < i and text[k].isdigit():
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != "'" and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            blank(i + 1, j)
            i = j + 1
            continue
        i += 1
    return "".join(out)


# ---- C++ function bodies --------------------------------------------------------------------

@dataclass
class Function:
    path: str
    line: int  # the signature's first line
    end_line: int  # the closing brace's line
    name: str

    @property
    def length(self) -> int:
        return self.end_line - self.line + 1


ACCESS_LABEL = re.compile(r"^\s*(?:public|private|protected)\s*:(?!:)\s*")
LAMBDA_TAIL = re.compile(
    r"\]\s*(?:\((?:[^()]|\([^()]*\))*\)\s*)?(?:(?:mutable|constexpr|consteval|static|noexcept(?:\([^()]*\))?)\s*)*"
    r"(?:->\s*[\w:<>,\s*&]+?)?\s*$")
CTOR_INIT = re.compile(r"\)\s*(?:noexcept\s*(?:\([^()]*\))?\s*)?:(?!:)")
CONTROL = re.compile(r"^(?:if|for|while|switch|catch|do|else|try|return)\b")
TYPE_KEYWORD = re.compile(r"^(?:(?:typedef|export)\s+)?(?:class|struct|union|enum)\b")
IDENT_BEFORE = re.compile(r"((?:[A-Za-z_]\w*\s*::\s*)*~?\s*[A-Za-z_]\w*(?:\s*<[^<>()]*>)?)\s*$")


def strip_template(head: str) -> str:
    """head without a leading template<...> (angle brackets matched)."""
    m = re.match(r"\s*template\s*<", head)
    while m:
        depth, k = 1, m.end()
        while k < len(head) and depth:
            depth += {"<": 1, ">": -1}.get(head[k], 0)
            k += 1
        head = head[k:]
        m = re.match(r"\s*template\s*<", head)
    return head.strip()


def top_level(head: str) -> list[tuple[int, str]]:
    """(index, char) of head's characters outside (), [] and <> (a '<' of operator<< or a
    comparison is rare in a declaration head)."""
    result, depth, angle = [], 0, 0
    for k, ch in enumerate(head):
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth = max(0, depth - 1)
        elif ch == "<" and depth == 0 and not head.startswith("operator", max(0, k - 8)):
            angle += 1
        elif ch == ">" and depth == 0 and angle and head[k - 1] != "-":
            angle -= 1
        elif depth == 0 and angle == 0:
            result.append((k, ch))
    return result


def has_top_level_assignment(head: str) -> bool:
    if re.search(r"\boperator\b", head):
        return False
    chars = top_level(head)
    for idx, (k, ch) in enumerate(chars):
        if ch != "=":
            continue
        prev = head[k - 1] if k else ""
        nxt = head[k + 1] if k + 1 < len(head) else ""
        if prev not in "=!<>+-*/%&|^" and nxt != "=":
            return True
    return False


def function_name(head: str) -> str:
    """The identifier before the head's first top-level '(' (operator names kept)."""
    m = re.search(r"\boperator\s*(?:\(\)|[^\s(]+)\s*\(", head)
    if m:
        before = IDENT_BEFORE.search(head[:m.start()] + "operator")
        return re.sub(r"\s+", "", (before.group(1) if before else "operator")) + head[m.start() + 8:m.end() - 1].strip()
    depth = 0
    for k, ch in enumerate(head):
        if ch == "<":
            depth += 1
        elif ch == ">" and depth and head[k - 1] != "-":
            depth -= 1
        elif ch == "(" and depth == 0:
            m = IDENT_BEFORE.search(head[:k])
            return re.sub(r"\s+", "", m.group(1)) if m else "?"
    return "?"


def classify(head: str) -> str:
    """What a '{' opens at namespace or class scope, from the text since the last ; { or }:
    namespace, class, function, lambda, init (a member's brace initialiser in a constructor's
    init list, or braces inside parentheses) or other (data, an enum's or an initialiser's
    braces)."""
    while ACCESS_LABEL.match(head):
        head = ACCESS_LABEL.sub("", head, count=1)
    bare = strip_template(head)
    if re.match(r"^(?:inline\s+)?namespace\b", bare) or re.fullmatch(r"extern\s*", bare):
        return "namespace"
    if LAMBDA_TAIL.search(head) and "]" in head:
        return "lambda"
    if head.count("(") > head.count(")"):
        return "init"  # a braced value inside parentheses: a default argument `= {}`, an argument
    if TYPE_KEYWORD.match(bare):
        return "class"
    if "(" not in bare or CONTROL.match(bare):
        return "other"
    if has_top_level_assignment(bare):
        return "other"
    init = CTOR_INIT.search(bare)
    if init and re.search(r"[\w>]\s*$", bare[init.end():]) and not re.search(r"\)\s*$", bare[init.end():]):
        return "init"
    return "function"


def cxx_functions(path: str, text: str) -> tuple[list[Function], list[str]]:
    """The functions of a C++ file (a lambda at namespace or class scope among them), and any
    problem found (unbalanced braces)."""
    code = blank_cxx(text)
    newlines = [k for k, ch in enumerate(code) if ch == "\n"]

    def line_of(offset: int) -> int:
        return bisect.bisect_right(newlines, offset - 1) + 1

    functions: list[Function] = []
    problems: list[str] = []
    # A stack of (kind, name, start line) per open brace.
    stack: list[tuple[str, str, int]] = []
    in_function = 0  # how many function/lambda entries are on the stack
    head_start = 0
    for k, ch in enumerate(code):
        if ch == ";":
            if not in_function:
                head_start = k + 1
        elif ch == "{":
            if in_function:
                stack.append(("inner", "", 0))
                continue
            head = code[head_start:k]
            kind = classify(head)
            if kind in ("function", "lambda"):
                body = head
                while ACCESS_LABEL.match(body):
                    body = ACCESS_LABEL.sub("", body, count=1)
                start = line_of(head_start + (len(head) - len(body)) + (len(body) - len(body.lstrip())))
                if kind == "function":
                    name = function_name(strip_template(body))
                else:
                    m = re.search(r"([A-Za-z_]\w*)\s*=[^=]*$", body[: body.rfind("]") + 1])
                    name = (m.group(1) if m else "lambda") + " (lambda)"
                stack.append((kind, name, start))
                in_function += 1
            else:
                stack.append((kind, "", 0))
                if kind != "init":  # a brace initialiser within the head: the head goes on
                    head_start = k + 1
        elif ch == "}":
            if not stack:
                problems.append(f"{path}:{line_of(k)}: unbalanced '}}'")
                continue
            kind, name, start = stack.pop()
            if kind in ("function", "lambda"):
                in_function -= 1
                if not in_function:
                    functions.append(Function(path, start, line_of(k), name))
                    head_start = k + 1
            elif kind == "init":
                pass  # the constructor's head goes on: the next '{' may be its body
            elif not in_function:
                head_start = k + 1
    if stack:
        problems.append(f"{path}: {len(stack)} unclosed '{{' (first: {stack[0][0]})")
    return functions, problems


def python_functions(path: str, text: str) -> tuple[list[Function], list[str]]:
    try:
        tree = ast.parse(text, filename=path)
    except SyntaxError as e:
        return [], [f"{path}:{e.lineno}: not Python: {e.msg}"]
    functions = []

    def visit(node: ast.AST, prefix: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                functions.append(Function(path, child.lineno, child.end_lineno, prefix + child.name))
                visit(child, prefix + child.name + ".")
            elif isinstance(child, ast.ClassDef):
                visit(child, prefix + child.name + ".")
            else:
                visit(child, prefix)

    visit(tree, "")
    return functions, []


# ---- the checks -------------------------------------------------------------------------

@dataclass
class Result:
    name: str
    offenders: list[str]
    summary: str
    problems: list[str]

    @property
    def ok(self) -> bool:
        return not self.offenders and not self.problems


class Source:
    def __init__(self, root: Path, files: list[str]):
        self.root = root
        self.files = files
        self._text: dict[str, str] = {}

    def text(self, rel: str) -> str:
        if rel not in self._text:
            self._text[rel] = (self.root / rel).read_text(encoding="utf-8", errors="replace")
        return self._text[rel]

    def lines(self, rel: str) -> int:
        t = self.text(rel)
        return t.count("\n") + (1 if t and not t.endswith("\n") else 0)


def check_functions(src: Source) -> Result:
    offenders, problems, count = [], [], 0
    for rel in src.files:
        finder = python_functions if rel.endswith(PY_EXTENSIONS) else cxx_functions
        functions, found_problems = finder(rel, src.text(rel))
        problems += found_problems
        count += len(functions)
        for f in functions:
            if f.length > MAX_FUNCTION_LINES:
                offenders.append(f"{rel}:{f.line}: {f.name} ({f.length} lines)")
    return Result("functions", offenders,
                  f"{len(offenders)} of {count} functions over {MAX_FUNCTION_LINES} lines", problems)


def check_files(src: Source) -> Result:
    offenders = [f"{rel}:1: {rel} ({src.lines(rel)} lines)" for rel in src.files if src.lines(rel) > MAX_FILE_LINES]
    return Result("files", offenders, f"{len(offenders)} of {len(src.files)} files over {MAX_FILE_LINES} lines", [])


def check_shells(src: Source) -> Result:
    total = sum(src.lines(rel) for rel in src.files)
    per_dir = {d: sum(src.lines(rel) for rel in src.files if rel.split("/")[0] == d) for d in SHELL_DIRS}
    shell = sum(per_dir.values())
    share = shell / total if total else 0.0
    parts = ", ".join(f"{d}/ {n}" for d, n in per_dir.items())
    summary = f"{parts}: {shell} of {total} lines = {100 * share:.1f} % (limit < {100 * MAX_SHELL_SHARE:.0f} %)"
    offenders = [] if share < MAX_SHELL_SHARE else [f"{d}/:1: {d}/ ({n} lines)" for d, n in per_dir.items()]
    return Result("shells", offenders, summary, [])


INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


SETUP_DECLARATION = re.compile(r"\bSetup[A-Z]\w*\s*\(")


def command_stems(src: Source) -> set[str]:
    """The cli/<stem> of each command: its source registers a subcommand (add_subcommand) or its
    header declares the function that sets one up (Setup<Name>, which the registry calls);
    the registry itself is none."""
    stems = set()
    registry = {rel.rsplit(".", 1)[0] for rel in REGISTRY_FILES}
    for rel in src.files:
        stem, ext = rel.rsplit(".", 1)
        if not rel.startswith("cli/") or stem in registry:
            continue
        code = blank_cxx(src.text(rel))
        if (ext == "cpp" and "add_subcommand(" in code) or (ext == "hpp" and SETUP_DECLARATION.search(code)):
            stems.add(stem)
    return stems


def cli_includes(src: Source, rel: str) -> list[tuple[int, str]]:
    """The quoted includes of a cli/ file: (line, the cli/ path they name)."""
    text = src.text(rel)
    found = []
    for m in INCLUDE.finditer(text):
        target = os.path.normpath(os.path.join(os.path.dirname(rel), m.group(1))).replace(os.sep, "/")
        if target not in src.files:
            target = "cli/" + m.group(1)  # the CLI's include directory is cli/
        found.append((text.count("\n", 0, m.start()) + 1, target))
    return found


def check_includes(src: Source) -> Result:
    commands = command_stems(src)
    cli_files = [rel for rel in src.files if rel.startswith("cli/") and not rel.endswith(PY_EXTENSIONS)]
    includes = {rel: cli_includes(src, rel) for rel in cli_files}
    # Each file's command: the command's own .cpp and .hpp, and its parts (cli/<stem>_*.* that
    # include cli/<stem>.hpp, e.g. simulate_body_region.cpp); None for a shared module.
    stems = {rel.rsplit(".", 1)[0] for rel in cli_files}
    stem_owner: dict[str, str | None] = {}
    for stem in stems:
        stem_owner[stem] = stem if stem in commands else None
        pair = [rel for rel in cli_files if rel.rsplit(".", 1)[0] == stem]
        for command in sorted(commands, key=len, reverse=True):
            if stem.startswith(command + "_") and any(t == command + ".hpp" for rel in pair for _, t in includes[rel]):
                stem_owner[stem] = command
                break
    owner = {rel: stem_owner[rel.rsplit(".", 1)[0]] for rel in cli_files}
    offenders = []
    for rel in cli_files:
        if rel in REGISTRY_FILES:
            continue
        for line, target in includes[rel]:
            command = owner.get(target)
            if command is not None and command != owner[rel]:
                who = f"command {owner[rel]}" if owner[rel] else "shared module"
                offenders.append(f"{rel}:{line}: {who} includes command {command}'s {target}")
    names = ", ".join(sorted(c[len("cli/"):] for c in commands))
    return Result("includes", offenders,
                  f"{len(offenders)} includes of a command's file from outside it (commands: {names})", [])


# The rules a shell must not write. Each: (name, regex, keep_strings). Matched line by line on
# the code with comments blanked (strings blanked too unless keep_strings).
RATIO = r"[\w.]*ratio\w*(?:\(\))?"
RULE_PATTERNS = [
    ("ratio compared with 1",
     re.compile(rf"\b{RATIO}\s*(?:<=|>=|<|>)\s*1(?:\.0*)?(?![\w.])|(?<![\w.])1(?:\.0*)?\s*(?:<=|>=|<|>)\s*[\w.>()*\s-]*ratio"),
     False),
    ("margin compared with 0",
     re.compile(r"\b[\w.]*margin\w*\s*(?:<=|>=|<|>)\s*0(?:\.0*)?(?![\w.])"), False),
    ("safety factor arithmetic (derating)",
     re.compile(r"\b(?:safety_factor|sf)\s*[*/](?!=)|[\w)\]]\s*[*/]\s*[\w.>()-]*?\b(?:safety_factor|sf)\b"), False),
    ("a safe/admissible flag decided by a comparison",
     re.compile(r"\b(?:\w+_)?(?:safe|unsafe|admissible|inadmissible|exceeded)\s*=(?!=)[^;]*?(?:<=|>=|(?<![-<])>(?![>=])|<(?![<=])|&&|\|\||\band\b|\bor\b)"),
     False),
    ("choosing the governing criterion",
     re.compile(r"\b(?:laceration|contusion|compression|crush|force|pressure)\w*ratio\w*\s*(?:<=|>=|<|>)\s*[\w.]*(?:laceration|contusion|compression|crush|force|pressure)\w*ratio"
                r"|\bstd::max\s*\([^;]*ratio[^;]*,[^;]*ratio|\bmax\s*\([^)]*ratio[^)]*,[^)]*ratio"
                r"|\b(?:governing|binding|binds|governs)\w*\s*=(?!=)[^;]*\?"),
     False),
    ("the bare robot's contact-area policy",
     re.compile(r"^(?=.*\bcontact_area\w*\s*(?:>|<=|==|!=)\s*0)(?=.*(?:covering|thickness|has_iso|limits|bare))"),
     False),
    ("contact-type policy",
     re.compile(r"\bif\s*\([^;]*ContactType::k\w+|\bhead\w*\s*=(?!=)[^;]*ContactType::k|\bcontact\s*(?:==|!=)\s*['\"](?:transient|clamped)['\"]"),
     False),
    ("region-name resolution",
     re.compile(r"""(?:==|!=)\s*["'](?:all|head)["']|["'](?:all|head)["']\s*(?:==|!=)|\bin\s*[(\[{]\s*["'](?:all|head)["']"""
                r"""|\bAllLimits\s*\(|(?:push_back\s*\(|[\w\]]\s*=\s*)["']all["']""", re.I),
     True),
]


def blank_python(text: str, keep_strings: bool) -> str:
    """Python text with comments (and, unless keep_strings, string literals) blanked."""
    lines = text.splitlines(keepends=True)
    out = [list(line) for line in lines]
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError):
        return text
    for tok in tokens:
        if tok.type == tokenize.COMMENT or (tok.type == tokenize.STRING and not keep_strings):
            (r0, c0), (r1, c1) = tok.start, tok.end
            for r in range(r0, r1 + 1):
                row = out[r - 1]
                a = c0 if r == r0 else 0
                b = c1 if r == r1 else len(row)
                inner = (a + 1, b - 1) if tok.type == tokenize.STRING and r0 == r1 else (a, b)
                for c in range(*inner):
                    if row[c] != "\n":
                        row[c] = " "
    return "".join("".join(row) for row in out)


def check_rules(src: Source) -> Result:
    offenders = []
    files = [rel for rel in src.files if rel.split("/")[0] in SHELL_DIRS]
    for rel in files:
        text = src.text(rel)
        python = rel.endswith(PY_EXTENSIONS)
        views = {keep: (blank_python(text, keep) if python else blank_cxx(text, keep)).splitlines()
                 for keep in (False, True)}
        original = text.splitlines()
        for name, pattern, keep in RULE_PATTERNS:
            for number, line in enumerate(views[keep], 1):
                m = pattern.search(line)
                # A match starting inside a string literal (blanked in the other view) is text.
                if m and keep and views[False][number - 1][m.start():m.start() + 1] != line[m.start()]:
                    m = next((m2 for m2 in pattern.finditer(line)
                              if views[False][number - 1][m2.start():m2.start() + 1] == line[m2.start()]), None)
                if m:
                    offenders.append(f"{rel}:{number}: {name}: {original[number - 1].strip()}")
    offenders.sort(key=lambda o: (o.split(":")[0], int(o.split(":")[1])))
    return Result("rules", offenders, f"{len(offenders)} lines in {len(files)} CLI/Python files write a library rule", [])


CHECK_FUNCTIONS = {"functions": check_functions, "files": check_files, "shells": check_shells,
                   "includes": check_includes, "rules": check_rules}


def run(root: Path, checks: list[str], out=sys.stdout) -> bool:
    src = Source(root, source_files(root))
    ok = True
    for name in checks:
        result = CHECK_FUNCTIONS[name](src)
        status = "ok" if result.ok else "FAIL"
        print(f"== {name}: {status}: {result.summary}", file=out)
        for line in result.offenders:
            print(f"  {line}", file=out)
        for line in result.problems:
            print(f"  cannot check: {line}", file=out)
        ok = ok and result.ok
    print(f"structure: {'ok' if ok else 'FAIL'} ({len(src.files)} source files under {root})", file=out)
    return ok


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent,
                        help="the repository (default: this script's)")
    parser.add_argument("--check", action="append", choices=CHECKS,
                        help="run only this check (repeatable); default all")
    parser.add_argument("--list-sources", action="store_true", help="print the files the checks cover and exit")
    args = parser.parse_args(argv)
    if not args.root.is_dir():
        parser.error(f"--root {args.root}: not a directory")
    if args.list_sources:
        print("\n".join(source_files(args.root)))
        return 0
    return 0 if run(args.root, args.check or list(CHECKS)) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
