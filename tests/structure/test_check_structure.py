#!/usr/bin/env python3
"""Self-test of scripts/check-structure.py: each check run on small trees it must reject (with
exactly the offenders named) and on trees it must accept, so that the structure test cannot
pass by finding nothing. Plain unittest (Python's standard library only)."""

from __future__ import annotations

import importlib.util
import io
import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "check-structure.py"
_spec = importlib.util.spec_from_file_location("check_structure", SCRIPT)
cs = importlib.util.module_from_spec(_spec)
sys.modules["check_structure"] = cs
_spec.loader.exec_module(cs)


def body_lines(n: int, indent: str = "  ") -> str:
    """n lines of statements."""
    return "".join(f"{indent}x += {k};\n" for k in range(n))


def cxx_function(name: str, length: int) -> str:
    """A C++ function `length` lines long, signature to closing brace, whose body holds braces
    in a comment, a string, a raw string, a character literal, a preprocessor line and a
    lambda: a scan that did not skip them would end it early or late."""
    tricky = ('  // } a brace in a comment\n'
              '  const char* s = "}}} {";\n'
              '  const char* r = R"x(a" } ")x";  // a raw string: no string ends at its inner quote\n'
              '  char c = \'}\';\n'
              '  if (1\'000\'000\'000 > x) {  // digit separators: no character literal\n'
              '    x = 1; }\n'
              '#define CLOSE }\n'
              '  auto f = [&](int v) {\n'
              '    return v + 1;\n'
              '  };\n'
              '  /* } */\n')
    fixed = 2 + tricky.count("\n") + 2  # the signature's 2 lines, the return, the closing brace
    return (f"int {name}(int x,\n        int y) {{\n" + tricky + body_lines(length - fixed)
            + "  return x + y + f(1);\n}\n")


def python_function(name: str, length: int) -> str:
    return f"def {name}(x):\n" + "".join(f"    x += {k}\n" for k in range(length - 2)) + "    return x\n"


def write(root: Path, files: dict[str, str]) -> None:
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text) if text.startswith("\n") else text)


class Tree(unittest.TestCase):
    def setUp(self) -> None:
        self.root = Path(tempfile.mkdtemp(prefix="covopt-structure-"))

    def tearDown(self) -> None:
        shutil.rmtree(self.root)

    def result(self, check: str) -> cs.Result:
        src = cs.Source(self.root, cs.source_files(self.root))
        return cs.CHECK_FUNCTIONS[check](src)

    def where(self, check: str) -> list[str]:
        """The offenders as 'path:line: name (length)' without the rest."""
        return self.result(check).offenders


class Functions(Tree):
    def test_a_function_of_101_lines_is_refused_and_one_of_100_accepted(self) -> None:
        write(self.root, {
            "core/src/long.cpp": "namespace covopt {\n" + cxx_function("TooLong", 101) + cxx_function("Fits", 100)
                                 + "}  // namespace covopt\n",
            "core/src/tool.py": python_function("too_long", 101) + python_function("fits", 100),
        })
        self.assertEqual(self.where("functions"), [
            "core/src/long.cpp:2: TooLong (101 lines)",
            "core/src/tool.py:1: too_long (101 lines)",
        ])

    def test_lengths_are_exact_for_the_usual_shapes(self) -> None:
        text = textwrap.dedent("""\
            #include <vector>
            namespace a::b {
            namespace {
            template <class T>
            std::vector<T> Make(T v)
            {
              return {v, v};
            }
            }  // namespace
            class Widget : public Base<int> {
             public:
              Widget(int a, int b) noexcept : a_{a}, b_(b), c_{Make(a)} {
                a_ += 1;
              }
              int Get() const { return a_; }
              bool operator==(const Widget& o) const {
                return a_ == o.a_;
              }
              enum class Kind : int { kOne = 1, kTwo = 2 };
             private:
              int a_{0};
              int b_ = 3;
            };
            const auto kLambda = [](int v) {
              return v;
            };
            const int kTable[] = {1, 2, 3}; const Widget kMade = Make(1, {2, 3});
            int Widget::Twice(Options o = {}, std::vector<int> v = {1, 2}) const {
              if (a_ > 0) {
                for (int i : {1, 2}) { b_ += i; }
              }
              return 2 * a_;
            }
            }  // namespace a::b
            extern "C" {
            int plain(void) { return 0; }
            }
            """)
        functions, problems = cs.cxx_functions("x.cpp", text)
        self.assertEqual(problems, [])
        self.assertEqual([(f.name, f.line, f.length) for f in functions], [
            ("Make", 4, 5), ("Widget", 12, 3), ("Get", 15, 1), ("operator==", 16, 3),
            ("kLambda (lambda)", 24, 3), ("Widget::Twice", 28, 6), ("plain", 36, 1)])

    def test_an_unbalanced_file_is_reported_not_passed(self) -> None:
        write(self.root, {"core/src/broken.cpp": "int f() {\n  return 1;\n"})
        result = self.result("functions")
        self.assertFalse(result.ok)
        self.assertEqual(len(result.problems), 1)
        self.assertIn("core/src/broken.cpp", result.problems[0])

    def test_tests_bench_fuzz_and_build_trees_are_not_source(self) -> None:
        long_function = cxx_function("Long", 150)
        write(self.root, {
            "tests/core/test_long.cpp": long_function,
            "bench/long.cpp": long_function,
            "fuzz/long.cpp": long_function,
            "python/tests/test_long.py": python_function("test_long", 150),
            "build/gen/long.cpp": long_function,
            "out/CMakeCache.txt": "",
            "out/gen/long.cpp": long_function,
            "core/src/short.cpp": cxx_function("Short", 10),
        })
        self.assertEqual(cs.source_files(self.root), ["core/src/short.cpp"])
        self.assertTrue(self.result("functions").ok)

    def test_a_git_checkout_takes_its_tracked_files(self) -> None:
        if shutil.which("git") is None:
            self.skipTest("no git")
        write(self.root, {"core/src/tracked.cpp": cxx_function("Tracked", 120),
                          "core/src/untracked.cpp": cxx_function("Untracked", 120)})
        run = lambda *args: subprocess.run(["git", "-C", str(self.root), *args], check=True, capture_output=True)
        run("init", "-q")
        run("add", "core/src/tracked.cpp")
        self.assertEqual(cs.source_files(self.root), ["core/src/tracked.cpp"])
        self.assertEqual(self.where("functions"), ["core/src/tracked.cpp:1: Tracked (120 lines)"])


class Files(Tree):
    def test_a_file_of_801_lines_is_refused_and_one_of_800_accepted(self) -> None:
        write(self.root, {"report/src/big.cpp": "int x;\n" * 801, "report/src/fits.cpp": "int x;\n" * 800,
                          "report/src/fits.py": "x = 1\n" * 800})
        self.assertEqual(self.where("files"), ["report/src/big.cpp:1: report/src/big.cpp (801 lines)"])


class Shells(Tree):
    def test_the_shells_share_is_refused_at_25_percent_and_accepted_below(self) -> None:
        write(self.root, {"core/a.cpp": "int x;\n" * 60, "cli/b.cpp": "int x;\n" * 10,
                          "python/c.py": "x = 1\n" * 10, "report/d.py": "x = 1\n" * 5})
        result = self.result("shells")
        self.assertTrue(result.ok, result.summary)
        self.assertIn("20 of 85 lines = 23.5 %", result.summary)
        write(self.root, {"python/e.py": "x = 1\n" * 2})  # 22 of 87 = 25.3 %
        result = self.result("shells")
        self.assertFalse(result.ok)
        self.assertIn("22 of 87 lines = 25.3 %", result.summary)


    def test_tools_docs_and_examples_are_not_source(self) -> None:
        write(self.root, {"core/a.cpp": "int x;\n" * 80, "cli/b.cpp": "int x;\n" * 19,
                          "scripts/tool.py": "x = 1\n" * 50, "docs/validation/v.py": "x = 1\n" * 50,
                          "python/examples/e.py": "x = 1\n" * 50})
        result = self.result("shells")
        self.assertTrue(result.ok, result.summary)
        self.assertIn("19 of 99 lines = 19.2 %", result.summary)
        self.assertEqual(cs.source_files(self.root), ["cli/b.cpp", "core/a.cpp"])


class Includes(Tree):
    COMMAND = '#include "{stem}.hpp"\n#include "shared.hpp"\nvoid Add{stem}(CLI::App& app) {{ app.add_subcommand("{stem}"); }}\n'

    def test_a_command_including_another_command_or_a_shared_module_reaching_one_is_refused(self) -> None:
        write(self.root, {
            "cli/app.cpp": '#include "alpha.hpp"\n#include "beta.hpp"\n',
            "cli/main.cpp": '#include "alpha.hpp"\n',
            "cli/alpha.cpp": self.COMMAND.format(stem="alpha"),
            "cli/alpha.hpp": '#include "shared.hpp"\n',
            "cli/beta.cpp": self.COMMAND.format(stem="beta") + '#include "alpha.hpp"\n',
            "cli/beta.hpp": '#include "shared.hpp"\n',
            "cli/shared.hpp": '#include "beta.hpp"\n',
            "cli/shared.cpp": '#include "shared.hpp"\n// app.add_subcommand( in a comment is no command\n',
        })
        self.assertEqual(self.where("includes"), [
            "cli/beta.cpp:4: command cli/beta includes command cli/alpha's cli/alpha.hpp",
            "cli/shared.hpp:1: shared module includes command cli/beta's cli/beta.hpp",
        ])

    def test_a_command_the_registry_sets_up_is_a_command_too(self) -> None:
        write(self.root, {
            "cli/app.cpp": '#include "alpha.hpp"\n#include "beta.hpp"\n'
                           'void Add(CLI::App& app) { SetupAlpha(app.add_subcommand("alpha")); }\n',
            "cli/app.hpp": "int RunCli();\n",
            "cli/main.cpp": '#include "app.hpp"\n',
            "cli/alpha.hpp": "void SetupAlpha(CLI::App* sub);\nint RunAlpha();\n",
            "cli/alpha.cpp": '#include "alpha.hpp"\n',
            "cli/beta.hpp": '#include "alpha.hpp"\nvoid SetupBeta(CLI::App* sub);\n',
            "cli/beta.cpp": '#include "beta.hpp"\n',
            "cli/shared.hpp": "// SetupGamma( in a comment is no command\nvoid AddSharedOptions(CLI::App* sub);\n",
            "cli/shared.cpp": '#include "shared.hpp"\n',
        })
        result = self.result("includes")
        self.assertEqual(result.offenders, ["cli/beta.hpp:1: command cli/beta includes command cli/alpha's cli/alpha.hpp"])
        self.assertIn("commands: alpha, beta)", result.summary)

    def test_a_commands_parts_are_its_own(self) -> None:
        write(self.root, {
            "cli/alpha.cpp": self.COMMAND.format(stem="alpha"),
            "cli/alpha.hpp": "struct Alpha {};\n",
            "cli/alpha_csv.hpp": '#include "alpha.hpp"\n',  # a part: it includes alpha.hpp
            "cli/alpha_csv.cpp": '#include "alpha_csv.hpp"\n',
            "cli/alpha_options.hpp": "struct Options {};\n",  # a shared module, whatever its name
            "cli/beta.cpp": self.COMMAND.format(stem="beta") + '#include "alpha_options.hpp"\n',
            "cli/beta_more.cpp": '#include "beta.hpp"\n#include "alpha_csv.hpp"\n',
        })
        self.assertEqual(self.where("includes"), [
            "cli/beta_more.cpp:2: command cli/beta includes command cli/alpha's cli/alpha_csv.hpp"])

    def test_commands_on_shared_modules_only_are_accepted(self) -> None:
        write(self.root, {
            "cli/app.cpp": '#include "alpha.hpp"\n#include "beta.hpp"\n',
            "cli/alpha.cpp": self.COMMAND.format(stem="alpha"),
            "cli/alpha.hpp": '#include "shared.hpp"\n',
            "cli/beta.cpp": self.COMMAND.format(stem="beta"),
            "cli/beta.hpp": '#include "shared.hpp"\n#include <covopt/optim/alpha.hpp>\n',
            "cli/shared.hpp": "struct Shared {};\n",
        })
        result = self.result("includes")
        self.assertTrue(result.ok, result.offenders)
        self.assertIn("commands: alpha, beta", result.summary)


class Rules(Tree):
    RULES_CXX = textwrap.dedent("""\
        bool Safe(double ratio) { return ratio <= 1.0; }
        bool Safe2(double r) { return 1 > r.laceration_ratio; }
        bool Ok(double margin) { return margin >= 0; }
        double Derated(const Plan& plan) { return 1.0 / plan.safety_factor; }
        double Scaled(double r, double sf) { return sf * r; }
        void F(Result& v) { v.admissible = v.ratio * 2 < limit && !v.crushed; }
        const Criterion c = lac.laceration_ratio > con.contusion_ratio ? kLac : kCon;
        void G(Result& v) { v.governing = a > b ? Criterion::kA : Criterion::kB; }
        void H(const Plan& regions) { if (regions.has_iso() && !(regions.contact_area_m2 > 0.0)) Warn(); }
        void I(const Plan& plan) { if (plan.contact == ContactType::kTransient) Add(); }
        bool J(const std::string& n) { return n == "all" || "head" == n; }
        void K(Flags& f) { f.regions.push_back("all"); }
        void L(const Table& t) { for (auto& l : t.AllLimits(c)) Use(l); }
        """)
    RULES_PY = textwrap.dedent("""\
        def pick(name, ratio, sf):
            safe = sf * ratio <= 1
            if name.lower() == "all":
                return max(lac_ratio, con_ratio)
            return name in ("head", "chest")
        """)
    PRINTING_CXX = textwrap.dedent("""\
        // ratio <= 1 in a comment; 1.0 / safety_factor; name == "all"
        /* margin >= 0 and safe = a < b */
        std::string_view SafeWord(bool safe) { return safe ? "SAFE" : "UNSAFE"; }
        void P(const Verdict& v) {
          fmt::print("ratio <= 1 / safety_factor: {} ({})\\n", v.governing_ratio, SafeWord(v.safe));
          fmt::print("{}", v.admissible ? "safe" : "NOT SAFE");
          throw InputError("body_region='all' takes every area; name == \\"head\\"");
          fmt::print("{}", regions.contact_area_m2 > 0.0 ? Area(regions.contact_area_m2) : "not given");
          const char* help = R"(--body-region all: ratio <= 1 )";
          plan.safety_factor = *extras.safety_factor;
          const bool worse = v.governing_ratio > worst;
          all ? "all" : "some";
        }
        """)
    PRINTING_PY = textwrap.dedent('''\
        def show(result):
            """body_region == "all" and ratio <= 1 in a docstring."""
            # safe = ratio <= 1 in a comment
            print(f"ratio {result.ratio} <= 1: {'SAFE' if result.safe else 'UNSAFE'}")
            return "head" if result.head else "all"
        ''')

    def test_each_rule_pattern_catches_its_rule(self) -> None:
        write(self.root, {"cli/rules.cpp": self.RULES_CXX, "python/covopt/rules.py": self.RULES_PY,
                          "core/src/library.cpp": self.RULES_CXX})  # the library may hold them
        found = {}
        for offender in self.where("rules"):
            path, line, rest = offender.split(":", 2)
            found.setdefault(f"{path}:{line}", set()).add(rest.split(":")[0].strip())
        self.assertEqual(found, {
            "cli/rules.cpp:1": {"ratio compared with 1"},
            "cli/rules.cpp:2": {"ratio compared with 1"},
            "cli/rules.cpp:3": {"margin compared with 0"},
            "cli/rules.cpp:4": {"safety factor arithmetic (derating)"},
            "cli/rules.cpp:5": {"safety factor arithmetic (derating)"},
            "cli/rules.cpp:6": {"a safe/admissible flag decided by a comparison"},
            "cli/rules.cpp:7": {"choosing the governing criterion"},
            "cli/rules.cpp:8": {"choosing the governing criterion"},
            "cli/rules.cpp:9": {"the bare robot's contact-area policy"},
            "cli/rules.cpp:10": {"contact-type policy"},
            "cli/rules.cpp:11": {"region-name resolution"},
            "cli/rules.cpp:12": {"region-name resolution"},
            "cli/rules.cpp:13": {"region-name resolution"},
            "python/covopt/rules.py:2": {"ratio compared with 1", "safety factor arithmetic (derating)",
                                         "a safe/admissible flag decided by a comparison"},
            "python/covopt/rules.py:3": {"region-name resolution"},
            "python/covopt/rules.py:4": {"choosing the governing criterion"},
            "python/covopt/rules.py:5": {"region-name resolution"},
        })

    def test_printing_comments_and_strings_are_not_rules(self) -> None:
        write(self.root, {"cli/print.cpp": self.PRINTING_CXX, "python/covopt/show.py": self.PRINTING_PY,
                          "python/tests/test_rules.py": self.RULES_PY})
        result = self.result("rules")
        self.assertTrue(result.ok, "\n".join(result.offenders))


class Main(Tree):
    def test_the_script_exits_1_and_names_each_failed_check(self) -> None:
        write(self.root, {"core/a.cpp": cxx_function("Long", 120), "cli/b.cpp": "int x;\n"})
        out = subprocess.run([sys.executable, str(SCRIPT), "--root", str(self.root)], capture_output=True, text=True)
        self.assertEqual(out.returncode, 1, out.stdout + out.stderr)
        self.assertIn("== functions: FAIL: 1 of 1 functions over 100 lines", out.stdout)
        self.assertIn("  core/a.cpp:1: Long (120 lines)", out.stdout)
        self.assertIn("== files: ok", out.stdout)
        self.assertIn("structure: FAIL", out.stdout)

    def test_the_script_exits_0_on_a_tree_that_keeps_every_rule(self) -> None:
        write(self.root, {"core/a.cpp": cxx_function("Short", 30), "cli/b.cpp": "int x;\n"})
        out = subprocess.run([sys.executable, str(SCRIPT), "--root", str(self.root)], capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
        self.assertIn("structure: ok (2 source files", out.stdout)

    def test_run_prints_a_summary_per_check(self) -> None:
        write(self.root, {"core/a.cpp": "int x;\n"})
        buffer = io.StringIO()
        self.assertTrue(cs.run(self.root, list(cs.CHECKS), out=buffer))
        self.assertEqual([line.split(":")[0] for line in buffer.getvalue().splitlines()[:5]],
                         [f"== {name}" for name in cs.CHECKS])


if __name__ == "__main__":
    unittest.main()
