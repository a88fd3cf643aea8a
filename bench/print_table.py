#!/usr/bin/env python3
"""Print table 5.1 of the thesis next to gaphys's reference and optimized variants.

From the repository root:

    cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DGAPHYS_BUILD_BENCHMARKS=ON
    cmake --build build-bench -j 2
    python3 bench/print_table.py --build-dir build-bench --repetitions 5 --json-dir build-bench/bench-json

It runs bench_table_5_1_{reference,instrumented,optimized}, bench_c3ga_kernels_{...} and
bench_world_step_{...} (found under --build-dir) with --benchmark_repetitions=N
--benchmark_format=json and prints Markdown tables: CPU seconds per 10,000,000 calls (median
over the repetitions), the reference / optimized ratio, the instrumented / reference overhead,
and the thesis's figures (seconds of user time for 10,000,000 calls); then the engine's step
time for N falling spheres with its split into phases. --tables algebra|engine picks one part.
--json-dir keeps the raw JSON; --from-json DIR prints the tables from a kept run without
running anything. Python 3 standard library only.
"""

import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

VARIANTS = ("reference", "instrumented", "optimized")
ALGEBRA_EXECUTABLES = ("bench_table_5_1", "bench_c3ga_kernels")
ENGINE_EXECUTABLES = ("bench_world_step",)
ENGINE_PHASES = (
    ("integration_ms", "integration"),
    ("pairs_ms", "pairs"),
    ("narrow_phase_ms", "narrow phase"),
    ("response_ms", "response"),
)

# Table 5.1 of the thesis: user seconds for 10,000,000 calls.
THESIS_COLUMNS = ("GATL", "Gaigen 2", "Gaigen 2 + profiling")
THESIS = {
    "add": (1.14, 13.96, 13.76),
    "gp": (1.63, 19.60, 0.14),
    "lc": (1.10, 13.86, 13.96),
    "op": (1.20, 15.74, 14.70),
    "scp": (1.08, 2.62, 2.14),
}
THESIS_NAMES = {"add": "plus / add", "lc": "lcont"}
FUNCTIONS = ("add", "gp", "lc", "op", "scp")
ARGUMENTS = ("mv", "vector", "bivector", "rotor", "motor")
ARGUMENT_LABELS = {
    "mv": "random full mv",
    "vector": "vectors",
    "bivector": "2-blades",
    "rotor": "rotors",
    "motor": "motors",
}
KERNELS = {
    "op4_points": "`p1 ^ p2 ^ p3 ^ p4` (sphere through 4 normalized points)",
    "apply_motor_point": "`apply(motor, normalized_point)`",
    "meet_dual_spheres": "`meet(dual(s1), dual(s2))` (circle of two dual spheres)",
    "gp_unprofiled": "`gp` on bitmaps the profile never saw (dispatch miss)",
}


def find_executable(build_dir, name):
    matches = sorted(p for p in Path(build_dir).rglob(name) if p.is_file())
    if not matches:
        sys.exit(f"print_table: {name} not found under {build_dir} (built with -DGAPHYS_BUILD_BENCHMARKS=ON?)")
    return matches[0]


def run(executable, args):
    command = [
        str(executable),
        f"--benchmark_repetitions={args.repetitions}",
        "--benchmark_report_aggregates_only=true",
        "--benchmark_enable_random_interleaving=true",
        "--benchmark_format=json",
    ]
    if args.min_time:
        command.append(f"--benchmark_min_time={args.min_time}")
    if args.filter:
        command.append(f"--benchmark_filter={args.filter}")
    print("print_table: running " + " ".join(command), file=sys.stderr, flush=True)
    return subprocess.run(command, check=True, stdout=subprocess.PIPE, text=True).stdout


def load_results(args, executables):
    """Returns {(variant, benchmark name): {"median": seconds, "cv": fraction}}, for the
    engine {(variant, benchmark name): {"median": entry, "cv": entry}} with Google Benchmark's
    JSON entries, a JSON context and the number of repetitions."""
    results, engine, context, repetitions = {}, {}, {}, set()
    for variant in VARIANTS:
        for name in executables:
            file_name = f"{name}_{variant}.json"
            if args.from_json:
                text = (Path(args.from_json) / file_name).read_text()
            else:
                text = run(find_executable(args.build_dir, f"{name}_{variant}"), args)
                if args.json_dir:
                    Path(args.json_dir).mkdir(parents=True, exist_ok=True)
                    (Path(args.json_dir) / file_name).write_text(text)
            if not text.strip():
                continue  # --filter matched none of this executable's benchmarks
            data = json.loads(text)
            context = data["context"]
            found = data["context"].get("gaphys_variant")
            if found != variant:
                sys.exit(f"print_table: {file_name} was produced by variant {found!r}, expected {variant!r}")
            for b in data["benchmarks"]:
                aggregate = b.get("aggregate_name")
                if aggregate not in ("median", "cv"):
                    continue
                repetitions.add(b["repetitions"])
                if name in ENGINE_EXECUTABLES:
                    engine.setdefault((variant, b["run_name"]), {})[aggregate] = b
                    continue
                # The cv of s_per_10M is a fraction; its median is in seconds.
                # (Loops timed per item, c3ga/apply_motor_points, report
                # items_per_second instead and are in no table.)
                if "s_per_10M" in b:
                    results.setdefault((variant, b["run_name"]), {})[aggregate] = b["s_per_10M"]
    return results, engine, context, "/".join(str(r) for r in sorted(repetitions))


def seconds(cell):
    if cell is None or "median" not in cell:
        return "n/a"
    text = f"{cell['median']:.3f}"
    if "cv" in cell:
        text += f" ±{100 * cell['cv']:.0f}%"
    return text


def ratio(reference, optimized):
    if not reference or not optimized or "median" not in reference or "median" not in optimized:
        return "n/a"
    return f"{reference['median'] / optimized['median']:.1f}x"


def function_label(function):
    return function + (f" ({THESIS_NAMES[function]})" if function in THESIS_NAMES else "")


def table_5_1_rows(results, algebra, suffix=""):
    """(function, argument, first row of its function, (reference, instrumented, optimized)) for
    every table 5.1 benchmark <algebra>/<function>/<argument><suffix> that ran."""
    for function in FUNCTIONS:
        first = True
        for argument in ARGUMENTS:
            name = f"{algebra}/{function}/{argument}{suffix}"
            cells = tuple(results.get((variant, name)) for variant in VARIANTS)
            if cells[0] is None and cells[2] is None:
                continue
            yield function, argument, first, cells
            first = False


def table_5_1(results, algebra, repetitions):
    lines = [
        f"#### {algebra}: `mv` arguments, CPU seconds per 10,000,000 calls (median of {repetitions}, ±cv)",
        "",
        "| function | arguments | reference | instrumented | optimized | ref / opt | instr / ref | "
        + " | ".join(f"thesis: {c}" for c in THESIS_COLUMNS)
        + " |",
        "|---|---|---:|---:|---:|---:|---:|" + "---:|" * len(THESIS_COLUMNS),
    ]
    for function, argument, first, (ref, ins, opt) in table_5_1_rows(results, algebra):
        thesis = [f"{t:.2f}" for t in THESIS[function]] if first else [""] * len(THESIS_COLUMNS)
        cells = [function_label(function) if first else "", ARGUMENT_LABELS[argument], seconds(ref), seconds(ins),
                 seconds(opt), ratio(ref, opt), ratio(ins, ref)]
        lines.append("| " + " | ".join(cells + thesis) + " |")
    return lines


def named_table(results, algebra, repetitions):
    """The table 5.1 operations on named types holding the same values as the mv rows,
    and how far the optimized mv path is from the named kernels (the issue's 2x bar)."""
    lines = [
        f"#### {algebra}: the same operands in named types, CPU seconds per 10,000,000 calls "
        f"(median of {repetitions}, ±cv)",
        "",
        "| function | arguments | reference | instrumented | optimized | optimized `mv` | `mv` / named |",
        "|---|---|---:|---:|---:|---:|---:|",
    ]
    for function, argument, first, (ref, ins, opt) in table_5_1_rows(results, algebra, "/named"):
        mv = results.get(("optimized", f"{algebra}/{function}/{argument}"))
        cells = [function_label(function) if first else "", ARGUMENT_LABELS[argument], seconds(ref), seconds(ins),
                 seconds(opt), seconds(mv), ratio(mv, opt)]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def kernel_table(results, repetitions):
    lines = [
        f"#### c3ga kernels: CPU seconds per 10,000,000 calls (median of {repetitions}, ±cv)",
        "",
        "| kernel | arguments | reference | instrumented | optimized | ref / opt | instr / ref |",
        "|---|---|---:|---:|---:|---:|---:|",
    ]
    for kernel, label in KERNELS.items():
        labelled = False  # the kernel's name goes on its first row
        for form, form_label in (("named", "named types"), ("mv", "same values in `mv`")):
            name = f"c3ga/{kernel}/{form}"
            ref, opt = results.get(("reference", name)), results.get(("optimized", name))
            ins = results.get(("instrumented", name))
            if ref is None and opt is None:
                continue
            cells = [label if not labelled else "", form_label, seconds(ref), seconds(ins), seconds(opt),
                     ratio(ref, opt), ratio(ins, ref)]
            labelled = True
            lines.append("| " + " | ".join(cells) + " |")
    return lines


def engine_run_name(results, variant, spheres, broad_phase="world_step"):
    """The run name of a world_step benchmark for this many spheres (it carries the iteration count)."""
    prefix = f"{broad_phase}/falling_spheres/{spheres}/"
    for found_variant, name in results:
        if found_variant == variant and name.startswith(prefix):
            return name
    return None


def milliseconds(value):
    return f"{value:.3f}" if value >= 0.01 else f"{value:.4f}"


def log_log_slope(points):
    """Least-squares slope of log(time) against log(N)."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mean_x, mean_y = sum(xs) / len(xs), sum(ys) / len(ys)
    covariance = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, ys))
    return covariance / sum((x - mean_x) ** 2 for x in xs)


def engine_table(engine, repetitions, broad_phase="world_step", sizes=(10, 100, 1000, 3000, 10000)):
    title = "uniform grid" if broad_phase == "world_step" else "all pairs (the thesis's broad phase)"
    lines = [
        f"#### Engine step, {title}: N spheres falling into a box, wall ms per step (median of {repetitions})",
        "",
        "| N | contacts | phase | reference | instrumented | optimized | ref / opt | instr / ref |",
        "|---:|---:|---|---:|---:|---:|---:|---:|",
    ]
    steps = {variant: [] for variant in VARIANTS}
    for spheres in sizes:
        cells = {}
        for variant in VARIANTS:
            name = engine_run_name(engine, variant, spheres, broad_phase)
            if name and "median" in engine[(variant, name)]:
                cells[variant] = engine[(variant, name)]
        if not cells:
            continue
        contacts = next(iter(cells.values()))["median"]["contacts"]
        rows = [("step (total)", lambda b: b["real_time"], "cv")] + [
            (label, lambda b, key=key: b[key], None) for key, label in ENGINE_PHASES
        ]
        for variant, cell in cells.items():
            steps[variant].append((spheres, cell["median"]["real_time"]))
        for index, (label, value, show_cv) in enumerate(rows):
            times = {v: value(c["median"]) for v, c in cells.items()}
            shown = []
            for variant in VARIANTS:
                if variant not in times:
                    shown.append("n/a")
                    continue
                text = milliseconds(times[variant])
                if show_cv and "cv" in cells[variant]:
                    text += f" ±{100 * cells[variant]['cv']['real_time']:.0f}%"
                shown.append(text)
            ref, ins, opt = (times.get(v) for v in VARIANTS)
            by = lambda a, b: f"{a / b:.1f}x" if a and b else "n/a"
            row = [str(spheres) if index == 0 else "", f"{contacts:.0f}" if index == 0 else "", label]
            lines.append("| " + " | ".join(row + shown + [by(ref, opt), by(ins, ref)]) + " |")
    slopes = []
    for variant in VARIANTS:
        points = [(n, t) for n, t in steps[variant] if n >= 100]
        if len(points) >= 2:
            slopes.append(f"{variant} {log_log_slope(points):.2f}")
    if slopes:
        lines += ["", "Log-log slope of step time against N over N >= 100: " + ", ".join(slopes) + "."]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--build-dir", default="build-bench", help="CMake build directory holding the benchmarks")
    source.add_argument("--from-json", metavar="DIR", help="read the JSON a previous run kept instead of running")
    parser.add_argument("--repetitions", type=int, default=5, help="benchmark repetitions; the table shows medians")
    parser.add_argument("--min-time", help="passed as --benchmark_min_time (e.g. 0.5, or 0.5s for benchmark >= 1.8)")
    parser.add_argument("--filter", help="passed as --benchmark_filter (a regex on the benchmark names)")
    parser.add_argument("--json-dir", metavar="DIR", help="keep each executable's JSON output here")
    parser.add_argument("--tables", choices=("all", "algebra", "engine"), default="all",
                        help="which tables to run and print (default all)")
    args = parser.parse_args()

    executables = ()
    if args.tables in ("all", "algebra"):
        executables += ALGEBRA_EXECUTABLES
    if args.tables in ("all", "engine"):
        executables += ENGINE_EXECUTABLES
    results, engine, context, repetitions = load_results(args, executables)
    lines = []
    if args.tables in ("all", "algebra"):
        for algebra in ("e3ga", "c3ga"):
            lines += table_5_1(results, algebra, repetitions) + [""]
            lines += named_table(results, algebra, repetitions) + [""]
        lines += kernel_table(results, repetitions) + [""]
    if args.tables in ("all", "engine"):
        lines += engine_table(engine, repetitions) + [""]
        lines += engine_table(engine, repetitions, "world_step_all_pairs", (10, 100, 1000)) + [""]
    lines.append(
        f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
        f"Google Benchmark library reports build type {context.get('library_build_type', '?')} "
        "(its own timing loop; the measured code is built with the project's flags). "
        "The thesis's figures are user seconds measured with `time` on its own machine and library versions."
    )
    print("\n".join(lines))


if __name__ == "__main__":
    main()
