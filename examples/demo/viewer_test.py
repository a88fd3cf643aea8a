#!/usr/bin/env python3
"""ctest demo_viewer: gaphys_demo --html pages, looked at in headless Chromium.

1. Where the sphere is drawn. bouncing_sphere is run with --out CSV and --html;
   the page is opened paused at two times with a fixed camera given in its
   fragment (eye, target, fov; z up, as the page documents), and screenshots
   are taken. With the sphere's centre at each time read from the CSV, the
   test projects it itself (a pinhole camera, as three.js's perspective one)
   and checks the screenshot: the sphere's colours around the projected centre,
   the page's background colour just outside the projected radius and where
   the sphere is at the other time. The eye is at the floor's height, so the
   translucent floor is seen edge on, as one line below the checked pixels.
2. How bodies are turned. spinning_body (a body tumbling about all three axes)
   is run the same way; the paused page writes each body's pose as drawn into
   <pre id="gaphys-state">, which --dump-dom prints. The images of the body's
   axes there must be those of the CSV's rotor R, x_world = R x_body ~R,
   computed here with a geometric product of its own.
3. Compound bodies. compound_table (a table of five boxes as one body, and a
   cube) is run with --out JSON, whose "bodies" give each body's shapes and
   their poses in it; the JSON must hold the table as the scene describes it.
   The paused page must hold one mesh per shape (and one per plane), and draw
   each shape's centre at x + R p ~R: the body's pose from the JSON's frame,
   the shape's offset p in the body from its "bodies".
4. Boxes. box_pyramid is run for a moment (it stands still) with --out CSV
   and --html; a screenshot with a fixed camera, the eye at the floor's
   height, must show a box at the projected centre of some of the 55, and the
   background just above the top one and beside the rows.
Every page must load without a JavaScript error (Chromium's console log).

Python 3 standard library only (the PNG decoder is below).
"""
import argparse
import csv
import html
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import zlib

WIDTH, HEIGHT = 480, 360
BACKGROUND = (0xE8, 0xEC, 0xF1)  # the page's background, #e8ecf1
# The page's overlays: the title at the top and the controls at the bottom.
# No pixel is checked within these margins.
TOP_MARGIN, BOTTOM_MARGIN = 84, 48
# The camera, set through the page's fragment: the eye at the floor's height
# (z = 0), off to the side, looking up a little.
EYE = (3.0, -9.0, 0.0)
TARGET = (0.6, 0.0, 1.6)
FOV = 40.0
SPHERE_RADIUS = 0.5  # gaphys::scenes::bouncing_sphere
SPHERE_ID = 1        # after the floor
# gaphys::scenes::compound_table: the top's half extents, and each leg's
# centre relative to the top's (the legs 0.7 m long under a 0.06 m top).
TABLE_TOP = (0.75, 0.45, 0.03)
TABLE_LEGS = [(x, y, -0.38) for x in (-0.68, 0.68) for y in (-0.38, 0.38)]
# gaphys::scenes::box_pyramid: 55 unit cubes; seen from the front with the
# eye at the floor's height, the whole pyramid between the page's overlays.
PYRAMID_BOXES = 55
PYRAMID_EYE = (4.0, -30.0, 0.0)
PYRAMID_TARGET = (0.0, 0.0, 4.5)
PYRAMID_FOV = 45.0


class Failure(Exception):
    pass


# ---- PNG -------------------------------------------------------------------------


def read_png(path):
    """(width, height, rows): rows[y][x] is an (r, g, b) tuple. 8-bit RGB or
    RGBA, not interlaced: what Chromium writes."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise Failure(f"{path} is not a PNG")
    position, compressed, header = 8, [], None
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        position += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            compressed.append(body)
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace != 0:
        raise Failure(f"{path}: PNG of depth {depth}, colour type {colour}, interlace "
                      f"{interlace}; this decoder reads 8-bit RGB(A) only")
    channels = 3 if colour == 2 else 4
    stride = width * channels
    raw = zlib.decompress(b"".join(compressed))
    rows, above = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 0xFF
        elif kind == 2:
            for i in range(stride):
                line[i] = (line[i] + above[i]) & 0xFF
        elif kind == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + above[i]) >> 1)) & 0xFF
        elif kind == 4:
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b = above[i]
                c = above[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else b if pb <= pc else c
                line[i] = (line[i] + predictor) & 0xFF
        elif kind != 0:
            raise Failure(f"{path}: unknown PNG filter {kind} in row {y}")
        rows.append([tuple(line[x:x + 3]) for x in range(0, stride, channels)])
        above = line
    return width, height, rows


# ---- geometry --------------------------------------------------------------------


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(dot(a, a))
    return tuple(x / n for x in a)


def project(point, width, height, eye=EYE, target=TARGET, fov=FOV):
    """Pixel (x right, y down) and depth of a world point, for a camera at eye
    looking at target with up +z and a vertical field of view fov."""
    forward = unit(sub(target, eye))
    right = unit(cross(forward, (0.0, 0.0, 1.0)))
    up = cross(right, forward)
    offset = sub(point, eye)
    depth = dot(offset, forward)
    focal = (height / 2) / math.tan(math.radians(fov) / 2)
    return (width / 2 + focal * dot(offset, right) / depth,
            height / 2 - focal * dot(offset, up) / depth, depth, focal)


# e3ga by bitmask blades (e1 = 1, e2 = 2, e3 = 4), Euclidean metric.
def geometric_product(a, b):
    result = {}
    for blade_a, x in a.items():
        for blade_b, y in b.items():
            swaps, shifted = 0, blade_a >> 1
            while shifted:
                swaps += bin(shifted & blade_b).count("1")
                shifted >>= 1
            sign = -1 if swaps % 2 else 1
            result[blade_a ^ blade_b] = result.get(blade_a ^ blade_b, 0.0) + sign * x * y
    return result


def rotate(rotor, vector):
    """R v ~R, rotor = (scalar, e12, e13, e23) as the demo writes it."""
    s, e12, e13, e23 = rotor
    r = {0: s, 3: e12, 5: e13, 6: e23}
    reverse = {0: s, 3: -e12, 5: -e13, 6: -e23}
    v = {1: vector[0], 2: vector[1], 4: vector[2]}
    image = geometric_product(geometric_product(r, v), reverse)
    return (image.get(1, 0.0), image.get(2, 0.0), image.get(4, 0.0))


# ---- running things --------------------------------------------------------------


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, timeout=120, **kwargs)
    if result.returncode != 0:
        raise Failure(f"{' '.join(command)} failed ({result.returncode}):\n{result.stderr}")
    return result.stdout


def run_page(chromium, work, *arguments):
    """Chromium on a page with its console logged to stderr; the standard
    output (the DOM with --dump-dom). A JavaScript error, uncaught or logged
    (three.js logs failed shaders as errors), fails the test."""
    command = chromium_command(chromium, work) + ["--enable-logging=stderr", "--v=0",
                                                  *arguments]
    result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        raise Failure(f"{' '.join(command)} failed ({result.returncode}):\n{result.stderr}")
    errors = [line for line in result.stderr.splitlines()
              if ":CONSOLE" in line and ("Uncaught" in line or "Error" in line)]
    if errors:
        raise Failure(f"{arguments[-1]} logged JavaScript errors:\n" + "\n".join(errors))
    return result.stdout


def chromium_command(chromium, work):
    """Headless Chromium with WebGL on SwiftShader, its CPU renderer (the GPU,
    if any, is not used: the pixels are the same on every machine). Without a
    sandbox: Chromium refuses to run as root with one, and containers often
    cannot give it one; the test opens only pages it has just made."""
    return [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
            "--use-angle=swiftshader", "--hide-scrollbars", "--mute-audio", "--no-first-run",
            "--no-default-browser-check", "--disable-extensions", "--disable-dev-shm-usage",
            f"--user-data-dir={os.path.join(work, 'chromium-profile')}",
            f"--window-size={WIDTH},{HEIGHT}"]


def page_state(chromium, work, page, fragment):
    """What the paused page writes into <pre id="gaphys-state">."""
    dom = run_page(chromium, work, "--dump-dom", page_url(page, fragment))
    found = re.search(r'<pre id="gaphys-state"[^>]*>(.*?)</pre>', dom, re.S)
    if not found or not found.group(1).strip():
        raise Failure(f"{page}#{fragment} wrote no state")
    return json.loads(html.unescape(found.group(1)))


def screenshot(chromium, work, page, fragment, name):
    """The page's pixels, rows[y][x]."""
    path = os.path.join(work, name)
    if os.path.exists(path):
        os.remove(path)
    run_page(chromium, work, f"--screenshot={path}", page_url(page, fragment))
    if not os.path.exists(path):
        raise Failure(f"Chromium took no screenshot of {page}#{fragment}")
    width, height, rows = read_png(path)
    if (width, height) != (WIDTH, HEIGHT):
        raise Failure(f"{path} is {width}x{height}, not {WIDTH}x{HEIGHT}")
    return rows


def page_url(page, fragment):
    return "file://" + os.path.abspath(page) + "#" + fragment


def trajectory(csv_path, body):
    """{time: ((x, y, z), (scalar, e12, e13, e23))} of one body."""
    poses = {}
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            if int(row["body"]) == body:
                poses[float(row["time"])] = (
                    tuple(float(row[k]) for k in ("x", "y", "z")),
                    tuple(float(row[k]) for k in ("r_scalar", "r_e12", "r_e13", "r_e23")))
    if not poses:
        raise Failure(f"{csv_path} has no rows of body {body}")
    return poses


def nearest(poses, t):
    return min(poses, key=lambda time: abs(time - t))


def far_from(colour, reference, tolerance):
    return max(abs(a - b) for a, b in zip(colour, reference)) > tolerance


# ---- the checks ------------------------------------------------------------------


def check_sphere_positions(args, work):
    csv_path, page = os.path.join(work, "bouncing.csv"), os.path.join(work, "bouncing.html")
    run([args.demo, "--scene", "bouncing_sphere", "--steps", "240", "--every", "6",
         "--out", csv_path, "--html", page])
    poses = trajectory(csv_path, SPHERE_ID)
    # At the top (t = 0) and near the floor, before the bounce (t = 0.6 s).
    times = [nearest(poses, 0.0), nearest(poses, 0.6)]
    centres = [poses[t][0] for t in times]
    if abs(centres[0][2] - centres[1][2]) < 1.0:
        raise Failure(f"the sphere moved too little to be told apart: {centres}")
    camera = "eye={},{},{}&target={},{},{}&fov={}".format(*EYE, *TARGET, FOV)
    for k, t in enumerate(times):
        rows = screenshot(args.chromium, work, page, f"t={t!r}&paused&{camera}",
                          f"bouncing_{k}.png")
        u, v, depth, focal = project(centres[k], WIDTH, HEIGHT)
        radius = focal * SPHERE_RADIUS / depth  # in pixels, near enough
        inside = [(u, v)] + [(u + 0.5 * radius * dx, v + 0.5 * radius * dy)
                             for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))]
        outside = [(u + 1.6 * radius, v), (u - 1.6 * radius, v), (u, v - 1.6 * radius)]
        other = project(centres[1 - k], WIDTH, HEIGHT)
        outside.append((other[0], other[1]))
        print(f"t = {t}: sphere at {centres[k]}, projected to ({u:.1f}, {v:.1f}), "
              f"radius {radius:.1f} px")
        wrong = 0
        for points, expected in ((inside, "sphere"), (outside, "background")):
            for x, y in points:
                px, py = int(round(x)), int(round(y))
                if not (0 <= px < WIDTH and TOP_MARGIN <= py < HEIGHT - BOTTOM_MARGIN):
                    raise Failure(f"the test's camera puts ({px}, {py}) off the checked area")
                colour = rows[py][px]
                # Background within 12 of the page's; sphere more than 40 away.
                if expected == "sphere":
                    good = far_from(colour, BACKGROUND, 40)
                else:
                    good = not far_from(colour, BACKGROUND, 12)
                wrong += not good
                print(f"  ({px}, {py}): {colour}, {expected} expected{'' if good else ' <- WRONG'}")
        if wrong:
            raise Failure(f"bouncing_{k}.png does not show the sphere where it is at t = {t}")


def check_attitudes(args, work):
    csv_path, page = os.path.join(work, "spinning.csv"), os.path.join(work, "spinning.html")
    run([args.demo, "--scene", "spinning_body", "--steps", "240", "--every", "24",
         "--out", csv_path, "--html", page])
    poses = trajectory(csv_path, 0)
    for wanted in (0.5, 0.9):
        t = nearest(poses, wanted)
        state = page_state(args.chromium, work, page, f"t={t!r}&paused")
        (body,) = state["bodies"]
        position, rotor = poses[t]
        worst = max(abs(a - b) for a, b in zip(body["position"], position))
        for axis, drawn in zip(((1, 0, 0), (0, 1, 0), (0, 0, 1)), body["axes"]):
            expected = rotate(rotor, axis)
            worst = max(worst, *(abs(a - b) for a, b in zip(drawn, expected)))
            print(f"t = {t}: body axis {axis} drawn as {[round(x, 6) for x in drawn]}, "
                  f"R x ~R = {[round(x, 6) for x in expected]}")
        if worst > 1e-5:
            raise Failure(f"at t = {t} the page turns the body otherwise than its rotor "
                          f"{rotor} (off by {worst})")


def check_compound(args, work):
    json_path, page = os.path.join(work, "table.json"), os.path.join(work, "table.html")
    run([args.demo, "--scene", "compound_table", "--steps", "240", "--every", "24",
         "--out", json_path, "--html", page])
    with open(json_path) as f:
        document = json.load(f)
    bodies = {body["id"]: body for body in document["bodies"]}
    tables = [body for body in bodies.values() if len(body["shapes"]) == 5]
    if len(tables) != 1:
        raise Failure(f"{json_path}: {len(tables)} bodies of five shapes, not one table")
    top, *legs = tables[0]["shapes"]
    worst = max(abs(a - b) for a, b in zip(top["half_extents"], TABLE_TOP))
    for leg, expected in zip(legs, TABLE_LEGS):
        worst = max(worst, *(abs(a - b - c) for a, b, c in
                             zip(leg["position"], top["position"], expected)))
    kinds = [shape["kind"] for shape in tables[0]["shapes"]]
    if kinds != ["box"] * 5 or worst > 1e-6:
        raise Failure(f"{json_path} holds a table of {kinds}, top {top}, legs {legs}: not the "
                      f"scene's (off by {worst})")
    print(f"the table's top and legs are where the scene puts them (within {worst:.2g} m)")

    for wanted in (0.3, 1.0):  # falling; then landed, the cube on it
        frame = min(document["frames"], key=lambda frame: abs(frame["time"] - wanted))
        t = frame["time"]
        state = page_state(args.chromium, work, page, f"t={t!r}&paused")
        # One mesh per shape; a plane, its body's only shape, is one mesh too.
        meshes = sum(len(body["shapes"]) for body in bodies.values())
        if state["meshes"] != meshes:
            raise Failure(f"at t = {t} the page holds {state['meshes']} meshes, not {meshes}")
        if len(state["bodies"]) != len(frame["bodies"]):
            raise Failure(f"at t = {t} the page draws {len(state['bodies'])} moving bodies, "
                          f"not {len(frame['bodies'])}")
        worst = 0.0
        for drawn, pose in zip(state["bodies"], frame["bodies"]):
            shapes = bodies[pose["id"]]["shapes"]
            kinds = [part["kind"] for part in drawn["parts"]]
            if drawn["id"] != pose["id"] or kinds != [shape["kind"] for shape in shapes]:
                raise Failure(f"at t = {t} body {drawn['id']} is drawn as {kinds}; body "
                              f"{pose['id']} has {[shape['kind'] for shape in shapes]}")
            for part, shape in zip(drawn["parts"], shapes):
                offset = rotate(pose["attitude"], shape["position"])
                expected = [x + r for x, r in zip(pose["position"], offset)]
                worst = max(worst, *(abs(a - b) for a, b in zip(part["position"], expected)))
        print(f"t = {t}: {state['meshes']} meshes; each shape drawn at x + R p ~R "
              f"(within {worst:.2g} m)")
        if worst > 1e-5:
            raise Failure(f"at t = {t} the page draws shapes off their poses by {worst} m")


def check_boxes(args, work):
    csv_path, page = os.path.join(work, "pyramid.csv"), os.path.join(work, "pyramid.html")
    run([args.demo, "--scene", "box_pyramid", "--steps", "48", "--every", "24",
         "--out", csv_path, "--html", page])
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    t = max(float(row["time"]) for row in rows)
    centres = [tuple(float(row[k]) for k in ("x", "y", "z"))
               for row in rows if float(row["time"]) == t]
    if len(centres) != PYRAMID_BOXES:
        raise Failure(f"{csv_path} has {len(centres)} boxes at t = {t}, not {PYRAMID_BOXES}")
    fragment = f"t={t!r}&paused&eye={{}},{{}},{{}}&target={{}},{{}},{{}}&fov={{}}".format(
        *PYRAMID_EYE, *PYRAMID_TARGET, PYRAMID_FOV)
    state = page_state(args.chromium, work, page, fragment)
    if state["meshes"] != PYRAMID_BOXES + 1:  # and the floor
        raise Failure(f"the pyramid's page holds {state['meshes']} meshes, not "
                      f"{PYRAMID_BOXES + 1}")
    pixels = screenshot(args.chromium, work, page, fragment, "pyramid.png")
    bottom = [c for c in centres if c[2] < 1]
    top = max(centres, key=lambda c: c[2])
    middle_row = [c for c in centres if 5 < c[2] < 6]
    boxes = [min(bottom), max(bottom), top, min(centres, key=lambda c: math.dist(c, (0, 0, 5)))]
    # 0.7 m above the top cube, and 1.2 m beside the ends of the row at 5.5 m.
    background = [(top[0], top[1], top[2] + 1.2),
                  (min(middle_row)[0] - 1.2, 0.0, 5.5), (max(middle_row)[0] + 1.2, 0.0, 5.5)]
    wrong = 0
    for points, expected in ((boxes, "box"), (background, "background")):
        for point in points:
            u, v, _, _ = project(point, WIDTH, HEIGHT, PYRAMID_EYE, PYRAMID_TARGET, PYRAMID_FOV)
            px, py = int(round(u)), int(round(v))
            if not (0 <= px < WIDTH and TOP_MARGIN <= py < HEIGHT - BOTTOM_MARGIN):
                raise Failure(f"the test's camera puts ({px}, {py}) off the checked area")
            colour = pixels[py][px]
            good = (far_from(colour, BACKGROUND, 40) if expected == "box"
                    else not far_from(colour, BACKGROUND, 12))
            wrong += not good
            print(f"  {tuple(round(x, 3) for x in point)} at ({px}, {py}): {colour}, {expected} "
                  f"expected{'' if good else ' <- WRONG'}")
    if wrong:
        raise Failure(f"pyramid.png does not show the boxes where they are at t = {t}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--demo", required=True, help="gaphys_demo")
    parser.add_argument("--chromium", required=True, help="Chromium (or Chrome)")
    parser.add_argument("--work", required=True, help="scratch directory (emptied first)")
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    try:
        check_sphere_positions(args, args.work)
        check_attitudes(args, args.work)
        check_compound(args, args.work)
        check_boxes(args, args.work)
    except Failure as failure:
        print(f"FAILED: {failure}", file=sys.stderr)
        return 1
    print("the viewer draws the sphere where it is, turns bodies as their rotors do, puts each "
          "shape of a compound body at its pose, and draws boxes where they are")
    return 0


if __name__ == "__main__":
    sys.exit(main())
