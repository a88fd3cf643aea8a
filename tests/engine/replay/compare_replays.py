#!/usr/bin/env python3
"""Replay across reruns and variants (run by ctest as engine_replay).

Runs each variant's replay executable twice for STEPS steps: the two runs must
print the same bytes (same build, same state hash); but see --exact. Then compares the variants
scene by scene: equal hashes mean bit-identical states; otherwise the largest
difference in any body's position, velocity, attitude or angular velocity must
stay within that scene's bound (see BOUNDS), and is printed.

    compare_replays.py [--float] [--exact NAME ...] STEPS NAME=EXECUTABLE [NAME=EXECUTABLE ...]

--exact NAME: that variant must be bit-identical to the first in every scene
(the instrumented variant computes with the reference's code and only adds
its recorder), in float too. Each of the two then runs once: another build
doing the same arithmetic that matches a run bit for bit is that run's rerun
(and a rerun of its own), so neither needs a second run.
--float (a GAPHYS_REAL=float build): the variants' differences are printed
but not bounded. The bounds below are double's rounding; in float the
reference's generic kernels (double tables, orthogonal-basis scaling) and
the optimized straight-line ones round differently even for spheres, and
a pile of falling spheres amplifies that into a different pile (0.16 m
after 1200 steps). Reruns must still be byte-identical.
"""

import subprocess
import sys

# Where both variants do the same arithmetic in the same order their states
# must stay bit-identical (bound 0): spheres have isotropic inertia, so the
# dynamics are e3ga vector sums, and the c3ga meets the optimized variant
# expands into straight-line code add the same terms in the same order as the
# reference's table. The spinning body turns its inertia through the rotor
# sandwich R I(~R B R) ~R, whose expanded kernels group the sums differently
# from the table: its states differ at rounding level (3e-13 after 2400
# steps), bounded here. Boxes, capsules and hulls turn too, and their
# contacts' arms go through the same sandwich: the stacks (tower, table) stay
# within 1e-13 after 1200 steps; the toppling scenes (dominoes, the mixed
# pile) are chaotic: each impact amplifies the rounding difference, up to
# 1e-3 m after 1200 steps for the dominoes' twenty impacts. Their bound
# checks that the same things happened (a domino that fell differently
# would be tens of centimetres away), not the rounding. Bounds are on the
# largest coordinate difference, SI.
BOUNDS = {
    "falling_spheres": 0.0,
    "sphere_column": 0.0,
    "elastic_collision": 0.0,
    "spinning_body": 1e-9,
    "bouncing_sphere": 0.0,
    "box_tower": 1e-9,
    "box_pyramid": 1e-9,
    "compound_table": 1e-9,
    "dominoes": 1e-2,
    "shape_mix": 1e-2,
}

def run(executable, steps):
    return subprocess.run([executable, str(steps)], check=True, stdout=subprocess.PIPE, text=True).stdout


def parse(text):
    """{scene: (hash, [[floats per body]])}"""
    scenes, current = {}, None
    for line in text.splitlines():
        words = line.split()
        if words[0] == "scene":
            current = words[1]
            scenes[current] = (words[2], [])
        else:
            scenes[current][1].append([float(w) for w in words[2:]])
    return scenes


def main():
    arguments = sys.argv[1:]
    bounded = "--float" not in arguments
    arguments = [a for a in arguments if a != "--float"]
    exact = set()
    while "--exact" in arguments:
        at = arguments.index("--exact")
        exact.add(arguments[at + 1])
        del arguments[at:at + 2]
    steps = int(arguments[0])
    variants = dict(argument.split("=", 1) for argument in arguments[1:])
    if not variants or not exact <= set(variants):
        print(f"usage: no variants, or --exact names one not given: {sorted(exact - set(variants))}")
        return 2
    outputs, failed = {}, False
    first_name = next(iter(variants))
    for name, executable in variants.items():
        first = run(executable, steps)
        checked_by_exact = name in exact or (name == first_name and bool(exact))
        second = first if checked_by_exact else run(executable, steps)
        if first != second:
            print(f"{name}: two runs of the same build differ")
            failed = True
        outputs[name] = parse(first)
    names = list(outputs)
    for other in names[1:]:
        for scene, (hash_a, bodies_a) in outputs[names[0]].items():
            hash_b, bodies_b = outputs[other][scene]
            if hash_a == hash_b:
                print(f"{scene}: {names[0]} and {other} bit-identical after {steps} steps")
                continue
            difference = max(abs(x - y) for a, b in zip(bodies_a, bodies_b) for x, y in zip(a, b))
            if other in exact:
                print(f"{scene}: {names[0]} and {other} differ by {difference:.3g} after {steps} steps "
                      "(NOT bit-identical, as they must be)")
                failed = True
                continue
            if not bounded:
                print(f"{scene}: {names[0]} and {other} differ by {difference:.3g} after {steps} steps "
                      "(float: not bounded)")
                continue
            verdict = "within" if difference <= BOUNDS[scene] else "OVER"
            print(f"{scene}: {names[0]} and {other} differ by {difference:.3g} after {steps} steps "
                  f"({verdict} the bound {BOUNDS[scene]:g})")
            failed = failed or difference > BOUNDS[scene]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
