#!/usr/bin/env python3
"""Whole-process time of a command A against a yardstick B, in pairs: A B A B ...

    python3 bench/startup/paired.py [-n RUNS] [--warmup N] --vs 'B ARGS' -- A ARGS

Each run is started with posix_spawn, its output thrown away, and reaped with wait4: wall is a
monotonic clock read just before the start and just after the reap, cpu the kernel's user + system
time of the finished child. Every figure is min / median / max; the ratio A/B is taken pair by
pair (so a machine whose speed drifts during the call still gives a meaningful ratio), and its
median is the figure to quote (bench/startup/measure.sh, docs/performance.md).
"""
import argparse
import os
import shlex
import statistics
import time


def run_once(argv, devnull):
    actions = [(os.POSIX_SPAWN_DUP2, devnull, 0), (os.POSIX_SPAWN_DUP2, devnull, 1),
               (os.POSIX_SPAWN_DUP2, devnull, 2)]
    start = time.perf_counter_ns()
    pid = os.posix_spawnp(argv[0], argv, os.environ, file_actions=actions)
    _, status, usage = os.wait4(pid, 0)
    wall = (time.perf_counter_ns() - start) * 1e-9
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{shlex.join(argv)} exited with {os.waitstatus_to_exitcode(status)}")
    return wall, usage.ru_utime + usage.ru_stime


def spread(values, unit=1.0, digits=3):
    return "  ".join(f"{f(values) * unit:.{digits}f}" for f in (min, statistics.median, max))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("-n", type=int, default=100, help="pairs timed (default 100)")
    parser.add_argument("--warmup", type=int, default=10, help="pairs run first, not timed (default 10)")
    parser.add_argument("--vs", required=True, help="the yardstick B, one string split as a shell splits words")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- A and its arguments")
    args = parser.parse_args()
    a = args.command[1:] if args.command[:1] == ["--"] else args.command
    b = shlex.split(args.vs)
    if not a:
        parser.error("no command A after --")
    times = {"A": [], "B": []}
    with open(os.devnull, "r+b") as null:
        for i in range(args.warmup + args.n):
            pair = {"A": run_once(a, null.fileno()), "B": run_once(b, null.fileno())}
            if i >= args.warmup:
                for key, value in pair.items():
                    times[key].append(value)
    print(f"A: {shlex.join(a)}\nB: {shlex.join(b)}\n{args.n} pairs after {args.warmup}; min  median  max")
    for key in ("A", "B"):
        print(f"{key} wall ms  {spread([w for w, _ in times[key]], 1e3)}")
        print(f"{key} cpu ms   {spread([c for _, c in times[key]], 1e3)}")
    for index, name in ((0, "wall"), (1, "cpu")):
        ratios = [ta[index] / tb[index] for ta, tb in zip(times["A"], times["B"]) if tb[index] > 0]
        print(f"A/B {name}     {spread(ratios, 1.0, 2)}")


if __name__ == "__main__":
    main()
