"""Variants of the procedural walk of tools/make_walk_bvh.py, written the way
other exporters write captures, each with answers known from its parameters:
for root-motion acceptance tests (issue #11). The command line is
make_walk_bvh.py's; see its --help.

Each variant starts from the straight, Y-up walk of make_walk_bvh.pose() and
changes it in this order:
  speed       the stride and the foot placement scale with the speed, the
              heel strike and push-off with its square root (short steps land
              flatter), the swing lifts the foot more; the 1.1 s cycle stays
              and the IK re-solves the legs, so the feet stay planted.
  turn        the walk bent onto a circle: frame by frame the whole body turns
              about the vertical through a point of the stance foot's sole (the
              one under the hips at mid-stance), and the stance foot turns back
              about it by as much, the leg twisting at the hip (about +-17 deg
              at 60 deg/s), so a planted foot keeps its place and heading; in
              swing the foot turns to its next heading. The yaw rate is
              rate(p) = w (1 - TURN_EASE cos(4 pi (p - 0.05))), p the cycle
              phase: its mean over every step is exactly w, and it is zero in
              the middle of each double support, where both feet are down and
              a turn would make them slide. The Hips then travel round a
              circle (to within ~5 cm), their heading along its tangent, and
              the straight stride is calibrated so the arc speed is the asked
              speed (pivoting on the feet shortens the path by ~1% at 60 deg/s).
  up axis     C times everything: C = Rx(+90 deg) for Z up ((x, y, z) ->
              (x, -z, y), Blender's convention, forward becomes -Y) or
              Rz(-90 deg) for X up ((x, y, z) -> (y, -x, z)). The root's
              position becomes C p and its rotation C R; for Z up its channels
              are Zrotation Yrotation Xrotation, because C R has a 90 deg X
              angle, the gimbal lock of ZXY.
  static root a ROOT joint_Root (OFFSET 0, six channels, zero in every frame)
              above Hips, which becomes a six-channel JOINT (OFFSET 0) with
              the root's motion: the same world positions in both readings of
              position channels (replace or add).
check() re-reads a file with its own reader and verifies it against the
generator's Y-up poses (every joint at C times its Y-up place), the gait
(feet, ground, stature) and the known answers, measured on the file.
"""
import json
import math
import os
import re

import make_walk_bvh as mw

SPEED = 1.3                # m/s of the default clip: STRIDE cm per 1.1 s cycle
SPEED_RANGE = (0.2, 1.6)   # m/s: faster, the fixed cycle's long strides crouch
MAX_TURN = 90.0            # deg/s
TURN_EASE = 1.0            # depth of the yaw-rate modulation, 0 = constant rate
IDENTITY = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
UP = {"y": IDENTITY, "z": mw.rot("X", 90), "x": mw.rot("Z", -90)}
ROOT_ORDER = {"y": "ZXY", "z": "ZYX", "x": "ZXY"}
POSITIONS = "Xposition Yposition Zposition "
# The acceptance-test clips (make_walk_bvh.py --suite): name, build() options.
SUITE = [
    ("yup_walk.bvh", {"cycles": 3}),
    ("static_root_walk.bvh", {"static_root": True, "cycles": 3}),
    ("zup_walk.bvh", {"up": "z", "cycles": 3}),
    ("xup_walk.bvh", {"up": "x", "cycles": 3}),
    ("curving_walk.bvh", {"turn_rate": -60.0, "cycles": 4}),
    ("slow_walk.bvh", {"speed": 0.35, "cycles": 4}),
    ("two_frames.bvh", {"frames": 2}),
]

NOTES = {
    "arc_speed_m_per_s": "ground speed along the path of the travel joint, averaged over whole cycles",
    "turn_rate_deg_per_s": "mean yaw rate about the up axis, positive = turning left (counter-clockwise "
                           "seen from above); within a step the rate swings between 0 and twice the mean",
    "stature_m": "crown of the head (Head End Site) minus the lowest sole point, standing in the rest pose",
    "up_axis": "the file's up axis; up_vector is it as a vector in the file's axes",
    "travel_joint": "the joint that carries the walk's translation (root_joint may be a static one)",
    "initial_forward": "the file-axes direction the walk starts along (frame 0, heading 0)",
    "turn_centre_m": "centre of the circle the Hips travel round, in the file's axes (up component 0)",
    "path_per_cycle_m": "path length per gait cycle (cycle_s)",
    "file_units_per_m": "the file is in centimetres",
}


def euler(m, order):
    """Angles in channel order with the rotations' product == m (ZXY or ZYX)."""
    if order == "ZXY":
        return mw.euler_zxy(m)
    assert order == "ZYX"
    return (math.degrees(math.atan2(m[1][0], m[0][0])),
            math.degrees(math.asin(max(-1.0, min(1.0, -m[2][0])))),
            math.degrees(math.atan2(m[2][1], m[2][2])))


def transpose(m):
    return tuple(zip(*m))


def set_speed(speed):
    """Rescales the stride-dependent gait parameters; speed SPEED keeps them exactly."""
    k = speed / SPEED
    mw.STRIDE, mw.FOOT_AHEAD = 143.0 * k, 32.0 * k
    # Short steps land flatter and push off less, but lift the foot as much.
    pitch = min(1.0, math.sqrt(k))
    mw.STRIKE_PITCH, mw.PUSH_PITCH, mw.TIP_PITCH = 18.0 * pitch, 70.0 * pitch, 25.0 * pitch
    mw.SWING_LIFT = 8.0 * max(1.0, 2.0 - k)
    mw._HEIGHTS.clear()   # the pelvis heights depend on the stride (and the turn)


# ---- turning ----
def turn_point():
    """The point of the sole, as a ground point from the flat left ankle, that
    the body and the stance foot turn about: the one under the hips at
    mid-stance (the ball of the foot at 1.3 m/s). Then the heading follows the
    path's tangent; turning about the middle of the sole, it would be ~2 deg off."""
    z = mw.STRIDE * mw.TOE_OFF / 2 - mw.FOOT_AHEAD
    z = max(mw.HEEL[2], min(mw.TOE_BASE[2] + mw.TIP[2], z))
    return mw.apply(mw.rot("Y", mw.TOE_OUT), (0.0, 0.0, z))


def lerp(a, b, s):
    return tuple(x + (y - x) * s for x, y in zip(a, b))


def pivot(f):
    """Centre of the body's turn at frame f in the straight walk's coordinates:
    the stance foot's turn_point(), gliding from the trailing to the leading
    foot during a double support (where the turn nearly stops)."""
    p, m = (f % mw.CYCLE_FRAMES) / mw.CYCLE_FRAMES, turn_point()
    down = sorted((q, sign) for sign, q in ((1, p), (-1, (p + 0.5) % 1.0)) if q <= mw.TOE_OFF)
    spots = [(sign * (mw.FOOT_TRACK + m[0]), 0.0,
              mw.STRIDE * f / mw.CYCLE_FRAMES + mw.FOOT_AHEAD + m[2] - mw.STRIDE * q) for q, sign in down]
    if len(spots) == 1:
        return spots[0]
    return lerp(spots[1], spots[0], mw.smoothstep(down[0][0] / (mw.TOE_OFF - 0.5)))


def foot_turn(rate):
    """make_walk_bvh.FOOT_TURN for a curving walk: a stance foot keeps the
    heading it has at mid-stance while the body turns over it, turning about
    turn_point() against the body; in swing it turns from one to the next."""
    cycle_frames = mw.CYCLE_FRAMES

    def yaw(q):   # degrees; periodic, the same for both legs (see heading())
        return math.degrees(heading(mw.TOE_OFF / 2 * cycle_frames, rate) - heading(q * cycle_frames, rate))

    def shift(q, sign):   # ankle displacement of that turn at stance phase q
        d = mw.add(mw.stance_foot(q)[0], turn_point(), -1)
        d = (sign * d[0], 0.0, d[2])
        return mw.add(mw.apply(mw.rot("Y", yaw(q)), d), d, -1), yaw(q)

    def turn(q, sign, target):
        if q <= mw.TOE_OFF:
            d, psi = shift(q, sign)
        else:
            e = mw.smoothstep((q - mw.TOE_OFF) / (1 - mw.TOE_OFF))
            (d0, psi0), (d1, psi1) = shift(mw.TOE_OFF, sign), shift(0.0, sign)
            d, psi = lerp(d0, d1, e), psi0 + (psi1 - psi0) * e
        return mw.add(target, d), psi
    return turn


def heading(f, rate):
    """Heading (radians) at frame f for a mean yaw rate in deg/s; see the docstring."""
    w, k, mid = math.radians(rate), 4 * math.pi, (mw.TOE_OFF - 0.5) / 2
    cycle = mw.CYCLE_FRAMES / mw.FPS
    p = f / mw.CYCLE_FRAMES
    return w * (f / mw.FPS - TURN_EASE * cycle / k * (math.sin(k * (p - mid)) + math.sin(k * mid)))


def turned(frames, rate):
    """frames bent onto a circle: world = Ry(heading) x + b, b integrated so the pivot stays put."""
    b, out = (0.0, 0.0, 0.0), []
    for f, (root, a) in enumerate(frames):
        if f:
            c = lerp(pivot(f - 1), pivot(f), 0.5)
            w = mw.add(mw.apply(mw.rot("Y", math.degrees(heading(f - 1, rate))), c), b)
            step = mw.rot("Y", math.degrees(heading(f, rate) - heading(f - 1, rate)))
            b = mw.add(mw.apply(step, mw.add(b, w, -1)), w)
        r = mw.rot("Y", math.degrees(heading(f, rate)))
        a = dict(a, Hips=mw.euler_zxy(mw.mul(r, mw.zxy(*a["Hips"]))))
        out.append((mw.add(mw.apply(r, root), b), a))
    return out


# ---- building a variant ----
def walk(speed, turn_rate, count):
    """Y-up frames (root, angles) of a straight or curving walk."""
    set_speed(speed)
    mw.FOOT_TURN = foot_turn(turn_rate) if turn_rate else None
    rows = [mw.pose(f) for f in range(count)]
    return turned(rows, turn_rate) if turn_rate else rows


def build(speed=SPEED, turn_rate=0.0, static_root=False, up="y", cycles=mw.CYCLES, frames=None):
    """The variant's skeleton, channels, frames (root, angles) and known answers,
    plus the Y-up poses it must match (reference worlds, original skeleton)."""
    count = frames if frames is not None else cycles * mw.CYCLE_FRAMES + 1
    straight = speed
    for _ in range(3 if turn_rate else 0):
        # Pivoting on the feet shortens the pelvis's path a little (~1% at 60
        # deg/s): lengthen the straight stride until the arc speed is right.
        one = walk(straight, turn_rate, mw.CYCLE_FRAMES + 1)
        straight *= speed / measure([mw.fk(mw.SKELETON, r, a) for r, a in one])[1]
    rows = walk(straight, turn_rate, count)
    worlds = [mw.fk(mw.SKELETON, r, a) for r, a in rows]
    centre = measure(worlds)[4] if turn_rate and len(worlds) > mw.CYCLE_FRAMES else None
    c, order = UP[up], ROOT_ORDER[up]
    if up != "y":
        rows = [(mw.apply(c, r), dict(a, Hips=euler(mw.mul(c, mw.zxy(*a["Hips"])), order)))
                for r, a in rows]
    skeleton, channels = mw.SKELETON, {"Hips": POSITIONS + rotations(order)}
    if static_root:
        skeleton = ([("joint_Root", None, (0, 0, 0), None), ("Hips", "joint_Root", (0, 0, 0), None)]
                    + mw.SKELETON[1:])
        channels["joint_Root"] = POSITIONS + rotations("ZXY")
        rows = [((0.0, 0.0, 0.0), dict(a, Hips=tuple(r) + tuple(a["Hips"]))) for r, a in rows]
    answers = {
        "arc_speed_m_per_s": speed, "turn_rate_deg_per_s": turn_rate,
        "stature_m": round(mw.standing_height(mw.SKELETON) / 100, 4), "up_axis": up,
        "travel_joint": "Hips", "root_joint": skeleton[0][0],
        "up_vector": [round(v) for v in mw.apply(c, (0, 1, 0))],
        "initial_forward": [round(v) for v in mw.apply(c, (0, 0, 1))],
        "turn_radius_m": round(abs(speed / math.radians(turn_rate)), 4) if turn_rate else None,
        "turn_centre_m": centre and [round(v / 100, 4) + 0.0 for v in mw.apply(c, (centre[0], 0, centre[1]))],
        "frame_count": count, "frame_time_s": round(1 / mw.FPS, 7), "fps": mw.FPS,
        "cycle_s": round(mw.CYCLE_FRAMES / mw.FPS, 4),
        "path_per_cycle_m": round(speed * mw.CYCLE_FRAMES / mw.FPS, 4),
        "file_units_per_m": 100, "static_root": static_root,
    }
    return {"skeleton": skeleton, "channels": channels, "frames": rows, "answers": answers,
            "reference": worlds, "up": c}


def rotations(order):
    return " ".join(axis + "rotation" for axis in order)


# ---- reading and checking ----
def read_bvh(path):
    """Small BVH reader, independent of the generator's tables: rows (name,
    parent, offset, end-site offset), channel names per joint, frame rows."""
    with open(path) as fh:
        lines = fh.read().split("\n")
    motion = lines.index("MOTION")
    skeleton, channels, stack = [], {}, []
    for tok in (line.split() for line in lines[:motion] if line.strip()):
        if tok[0] in ("ROOT", "JOINT"):
            skeleton.append([tok[1], stack[-1] if stack else None, None, None])
            stack.append(tok[1])
        elif tok[0] == "End":
            stack.append(None)
        elif tok[0] == "OFFSET":   # an End Site's offset is stored on its joint
            joint = next(r for r in skeleton if r[0] == (stack[-1] or stack[-2]))
            joint[2 if stack[-1] else 3] = tuple(float(x) for x in tok[1:4])
        elif tok[0] == "CHANNELS":
            channels[stack[-1]] = tok[2:]
        elif tok[0] == "}":
            stack.pop()
    rows = [[float(x) for x in line.split()] for line in lines[motion + 3:] if line.strip()]
    return [tuple(r) for r in skeleton], channels, int(lines[motion + 1].split()[1]), rows


def file_worlds(skeleton, channels, row, undo):
    """World (position, rotation) per joint of one frame, position channels
    replacing the OFFSET, then turned by `undo` (back to Y up)."""
    out, k = {}, 0
    for name, parent, offset, _ in skeleton:
        values = dict(zip(channels[name], row[k:k + len(channels[name])]))
        k += len(channels[name])
        local = IDENTITY
        for ch in channels[name]:
            if ch.endswith("rotation"):
                local = mw.mul(local, mw.rot(ch[0], values[ch]))
        t = tuple(values.get(a + "position", o) for a, o in zip("XYZ", offset))
        ppos, prot = out[parent] if parent else ((0, 0, 0), undo)
        out[name] = (mw.add(ppos, mw.apply(prot, t)), mw.mul(prot, local))
    return out


def rigid_yaw(w0, w1):
    """Yaw (radians, about +Y) and translation that best carry the joints of w0
    onto w1, and the largest distance left."""
    names = [r[0] for r in mw.SKELETON]
    u, v = [w0[n][0] for n in names], [w1[n][0] for n in names]
    cu, cv = [sum(p[i] for p in u) / len(u) for i in range(3)], [sum(p[i] for p in v) / len(v) for i in range(3)]
    du, dv = [mw.add(p, cu, -1) for p in u], [mw.add(p, cv, -1) for p in v]
    phi = math.atan2(sum(b[0] * a[2] - b[2] * a[0] for a, b in zip(du, dv)),
                     sum(b[0] * a[0] + b[2] * a[2] for a, b in zip(du, dv)))
    r = mw.rot("Y", math.degrees(phi))
    t = mw.add(cv, mw.apply(r, cu), -1)
    residual = max(math.dist(mw.add(mw.apply(r, a), t), b) for a, b in zip(u, v))
    return phi, t, residual


def measure(worlds):
    """From the rigid motion that carries each whole cycle's first frame onto
    the next one's (Y up, cm): turn rate (deg/s), arc speed (m/s) of the Hips'
    ground path, the largest loop residual (cm), the crab angle (deg) and the
    turn's centre (x, z in cm; None on a straight walk). None if the clip is
    shorter than a cycle."""
    n = mw.CYCLE_FRAMES
    k = (len(worlds) - 1) // n * n
    if not k:
        return None
    moves = [rigid_yaw(worlds[i], worlds[i + n]) for i in range(0, k, n)]
    (phi, t, _), residual = moves[0], max(r for *_, r in moves)
    seconds = k / mw.FPS
    if abs(phi) < 1e-9:
        return 0.0, math.hypot(t[0], t[2]) / 100 * mw.FPS / n, residual, crab(worlds[:n], lambda p: t), None
    # Centre of the turn: the fixed point o = R o + t of the per-cycle motion.
    c, s = math.cos(phi), math.sin(phi)
    a, b, d, e = 1 - c, -s, s, 1 - c   # (I - R) restricted to (x, z)
    det = a * e - b * d
    o = ((e * t[0] - b * t[2]) / det, (a * t[2] - d * t[0]) / det)
    sense = math.copysign(1.0, phi)   # tangent of the circle about o at p
    tangent = lambda p: (sense * (p[2] - o[1]), 0.0, -sense * (p[0] - o[0]))
    # Arc length: radius times swept angle of the Hips about o, frame by frame.
    arc, prev = 0.0, None
    for w in worlds[:k + 1]:
        x, z = w["Hips"][0][0] - o[0], w["Hips"][0][2] - o[1]
        ang = math.atan2(x, z)
        if prev:
            arc += (math.hypot(x, z) + prev[1]) / 2 * abs(math.remainder(ang - prev[0], 2 * math.pi))
        prev = (ang, math.hypot(x, z))
    return (math.degrees(sum(m[0] for m in moves)) / seconds, arc / 100 / seconds, residual,
            crab(worlds[:n], tangent), o)


def crab(worlds, tangent):
    """Mean angle (deg) of the heading (hip line x up) from the path's tangent
    at the Hips, over frames spanning one cycle (the pelvis's yaw swing cancels)."""
    total = 0.0
    for w in worlds:
        d, v = mw.add(w["LeftUpLeg"][0], w["RightUpLeg"][0], -1), tangent(w["Hips"][0])
        total += math.remainder(math.atan2(-d[2], d[0]) - math.atan2(v[0], v[2]), 2 * math.pi)
    return math.degrees(total / len(worlds))


def check(path, clip):
    """Re-reads path and verifies it; prints one line per verdict; True if all pass."""
    skeleton, channels, n_frames, rows = read_bvh(path)
    undo, answers, ok = transpose(clip["up"]), clip["answers"], True

    def verdict(label, good, detail):
        nonlocal ok
        ok &= good
        print(f"  {'ok  ' if good else 'FAIL'} {label}: {detail}")

    print(f"check {path}:")
    total = sum(len(c) for c in channels.values())
    verdict("joints >= 25", len(skeleton) >= 25, len(skeleton))
    verdict("values per line", len(rows) == n_frames and all(len(r) == total for r in rows),
            f"{total} channels; {len(rows)} rows of {sorted({len(r) for r in rows})} values; "
            f"Frames: {n_frames}")
    worlds = [file_worlds(skeleton, channels, r, undo) for r in rows]
    err = max(math.dist(w[n][0], ref[n][0]) for w, ref in zip(worlds, clip["reference"])
              for n, *_ in mw.SKELETON)
    verdict("joints where the Y-up walk puts them", err < 0.01,
            f"every joint within {err:.4f} cm of C x its Y-up place, C = {answers['up_axis']}-up")
    m = measure(worlds)
    if m:
        cycles = (len(worlds) - 1) // mw.CYCLE_FRAMES
        verdict("loop closed", m[2] < 0.01, f"each of {cycles} cycles ends on its first frame moved "
                f"rigidly, to within {m[2]:.4f} cm")
        verdict("turn rate", abs(m[0] - answers["turn_rate_deg_per_s"]) < 0.05,
                f"{m[0]:.3f} deg/s (known answer {answers['turn_rate_deg_per_s']})")
        verdict("arc speed", abs(m[1] / answers["arc_speed_m_per_s"] - 1) < 0.01,
                f"Hips ground path {m[1]:.4f} m/s (known answer {answers['arc_speed_m_per_s']})")
        verdict("heading along the path", abs(m[3]) < 0.5,
                f"hip line off the path's tangent by {m[3]:.3f} deg on average")
    slip, hover, lowest = mw.foot_metrics(worlds)
    tip = next(r[3] for r in skeleton if r[0] == "LeftToeBase")
    toe_min = min(mw.point(w, t, tip)[1] for w in worlds for t in ("LeftToeBase", "RightToeBase"))
    if m:
        verdict("toe touches ground", abs(toe_min) < 2.0, f"min toe End Site height {toe_min:.2f} cm")
    verdict("no sole below ground", lowest > -1.0, f"lowest sole point {lowest:.2f} cm")
    stature = mw.standing_height(skeleton)
    crown = [mw.point(w, "Head", next(r[3] for r in skeleton if r[0] == "Head"))[1] for w in worlds]
    verdict("stature", abs(stature - 100 * answers["stature_m"]) < 0.01,
            f"standing {stature:.2f} cm (known answer {answers['stature_m']} m); walking: head top "
            f"{min(crown):.1f}-{max(crown):.1f} cm")
    verdict("stance slip < 5 cm/step", slip < 5, f"{slip:.2f} cm, stance hover <= {hover:.2f} cm")
    return ok


def write_suite(directory):
    """The acceptance-test clips and known_answers.json; False if a check fails."""
    os.makedirs(directory, exist_ok=True)
    answers, ok = {}, True
    for name, options in SUITE:
        clip = build(**options)
        path = os.path.join(directory, name)
        mw.write_bvh(path, clip["frames"], clip["skeleton"], clip["channels"])
        ok &= check(path, clip)
        answers[name] = dict(clip["answers"], options=options)
    text = json.dumps({"generator": "tools/make_walk_bvh.py --suite", "notes": NOTES, "clips": answers},
                      indent=2)
    text = re.sub(r"\[\s+([^][{}]*?)\s+\]",   # lists of numbers on one line
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text)
    with open(os.path.join(directory, "known_answers.json"), "w", newline="\n") as fh:
        fh.write(text + "\n")
    return ok
