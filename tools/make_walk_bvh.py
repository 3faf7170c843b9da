#!/usr/bin/env python3
"""Write Throng's built-in motion clip, a procedural human walk cycle, as BVH.

Usage: tools/make_walk_bvh.py [--out assets/walk.bvh] [--check] [variant options]
       tools/make_walk_bvh.py --suite DIR

Throng must run without outside files, so it generates its own default clip.
Output is deterministic. Centimetres, Y up, the character walks along +Z and
its left is +X; channels are Zrotation Xrotation Yrotation in degrees with
local = T(offset) * Rz * Rx * Ry, so a positive Xrotation swings a hanging
limb backwards (hip flexion and ankle dorsiflexion are negative X).

Pelvis sway/roll/yaw, spine, arms and head are sums of sinusoids of the gait
phase. The legs are not, because angle curves alone always let the stance
foot skate: each foot follows a planted heel-to-toe roll in stance and a
smooth arc in swing, and the leg angles are solved from it (two-bone IK). The
pelvis height is solved so the stance knee follows a gait-lab curve.

Variants, test captures with answers known from their parameters:
  --speed M_PER_S      ground speed, 0.2-1.6 (default 1.3): the stride scales,
                       the 1.1 s cycle stays, the feet stay planted (IK)
  --turn-rate DEG_S    the walk curves on a circle at this mean yaw rate, up to
                       +-90 (about +Y; positive turns left, from +Z towards +X),
                       pivoting on the planted foot, at the asked arc speed
  --static-root        an extra ROOT joint_Root (OFFSET 0, 6 channels, all zero)
                       above Hips, which becomes a 6-channel JOINT with the motion
  --up z | x           the file's up axis: Z up is the capture turned +90 deg about
                       X ((x, y, z) -> (x, -z, y)), X up -90 deg about Z
                       ((x, y, z) -> (y, -x, z)); every joint lands at C times its
                       Y-up place
  --cycles N           N gait cycles, N x 66 + 1 frames (default 2)
  --frames N           just the first N frames
  --suite DIR          the root-motion acceptance clips (walk_variants.SUITE) and
                       known_answers.json (arc speed, turn rate, stature, up axis,
                       travel joint of each) in DIR, each checked
A variant needs --out. --check re-reads the file and verifies the joints
against the Y-up walk, the loop, the gait and the known answers. How each
variant is made: tools/walk_variants.py.
"""
import argparse
import math
import os
import sys

FPS = 60
CYCLE_FRAMES = 66          # 1.1 s gait cycle (two steps) at 60 fps
CYCLES = 2
STRIDE = 143.0             # cm per cycle: 1.3 m/s * 1.1 s

# (name, parent, offset, end-site offset or None); the right side mirrors the
# left. CMU joint names so retargeting tools recognise the skeleton. No bone
# has zero length, because the viewer draws joints as spheres.
THIGH = SHIN = 41.0
LEFT_LEG = [
    ("LHipJoint", "Hips", (4.5, -2.5, 0), None),
    ("LeftUpLeg", "LHipJoint", (4.5, -2.5, 0), None),        # hip joint 90 cm up
    ("LeftLeg", "LeftUpLeg", (0, -THIGH, 0), None),
    ("LeftFoot", "LeftLeg", (0, -SHIN, 0), None),             # ankle 8 cm up
    ("LeftToeBase", "LeftFoot", (0, -6, 12), (0, -1.5, 7)),   # ball of the foot
]
SPINE = [
    ("LowerBack", "Hips", (0, 4, 0), None),
    ("Spine", "LowerBack", (0, 11, 0), None),
    ("Spine1", "Spine", (0, 12, 0), None),
    ("Neck", "Spine1", (0, 24, 0), None),
    ("Neck1", "Neck", (0, 6, 0), None),
    ("Head", "Neck1", (0, 6, 0), (0, 17, 0)),                 # crown at 175 cm
]
LEFT_ARM = [
    ("LeftShoulder", "Spine1", (3, 20, 0), None),
    ("LeftArm", "LeftShoulder", (15, 3, 0), None),            # shoulder at 145 cm
    ("LeftForeArm", "LeftArm", (30, 0, 0), None),
    ("LeftHand", "LeftForeArm", (26, 0, 0), None),
    ("LeftFingerBase", "LeftHand", (4, 0, 0), None),
    ("LeftHandIndex1", "LeftFingerBase", (4, 0, 0), (4, 0, 0)),
    ("LThumb", "LeftHand", (1.5, -0.5, 2.5), (2.5, 0, 2.5)),
]


def mirrored(rows):
    def name(n):
        return n.replace("Left", "Right").replace("LHip", "RHip").replace("LThumb", "RThumb")

    def flip(v):
        return v and (-v[0], v[1], v[2])
    return [(name(n), name(p), flip(o), flip(e)) for n, p, o, e in rows]


SKELETON = ([("Hips", None, (0, 0, 0), None)] + LEFT_LEG + mirrored(LEFT_LEG) + SPINE
            + LEFT_ARM + mirrored(LEFT_ARM))
HIP = tuple(a + b for a, b in zip(LEFT_LEG[0][2], LEFT_LEG[1][2]))   # left hip joint from root
TOE_BASE = LEFT_LEG[-1][2]
HEEL = (0, -8, -6)         # sole under the heel, in the ankle's frame
BALL = (0, -2, 0)          # sole under the ball and under the toe tip, in the
TIP = (0, -2, 7)           # toe's frame (points for ground contact, not joints)

# Foot timeline of one leg in fractions of the cycle from its heel strike
# (typical gait-lab timings): heel rocker until FLAT, foot flat until
# HEEL_OFF, rolling over the ball and from TIP_ON onto the toe tip, swing
# from TOE_OFF.
FLAT, HEEL_OFF, TIP_ON, TOE_OFF = 0.10, 0.32, 0.48, 0.60
STRIKE_PITCH = 18.0        # foot pitch (toes up) at heel strike
PUSH_PITCH, TIP_PITCH = 70.0, 25.0   # foot and toe pitch (toes down) at toe-off
FOOT_AHEAD = 32.0          # flat-foot ankle ahead of the hips at heel strike
FOOT_TRACK = 7.0           # ankles travel on the lines x = +-7 cm
TOE_OUT = 5.0
SWING_LIFT = 8.0           # extra ankle lift early in swing: toe clearance, knee bend
SWING_ANKLE = -3.0         # ankle X mid-swing: slight dorsiflexion clears the toes
TOE_RELAX = 0.4            # share of swing over which the toes straighten
# Stance knee flexion (phase, degrees), gait-lab shape with the loading bump.
STANCE_KNEE = [(0.0, 4.0), (0.15, 17.0), (0.40, 6.0), (0.60, 25.0)]
HEIGHT_SMOOTHING = 0.04    # half-width (cycles) of the pelvis height smoothing window
SWAY, ROLL, YAW, LEAN = 2.0, 2.5, 4.0, 3.0  # pelvis sway (cm), roll, yaw, trunk lean (deg)
ARM_DOWN, ARM_SWING, ELBOW = 75.0, 14.0, 15.0
FOOT_TURN = None           # walk_variants: (q, sign, ankle target) -> (ankle target, foot yaw)


# ---- 3x3 rotation maths, matrices as tuples of rows ----
def rot(axis, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return {"X": ((1, 0, 0), (0, c, -s), (0, s, c)), "Y": ((c, 0, s), (0, 1, 0), (-s, 0, c)),
            "Z": ((c, -s, 0), (s, c, 0), (0, 0, 1))}[axis]


def mul(a, b):
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3))
                 for i in range(3))


def apply(m, v):
    return tuple(sum(m[i][k] * v[k] for k in range(3)) for i in range(3))


def add(a, b, k=1.0):
    return tuple(x + k * y for x, y in zip(a, b))


def zxy(z, x, y):
    return mul(mul(rot("Z", z), rot("X", x)), rot("Y", y))


def euler_zxy(m):
    """(z, x, y) in degrees with zxy(z, x, y) == m."""
    x = math.asin(max(-1.0, min(1.0, m[2][1])))
    return (math.degrees(math.atan2(-m[0][1], m[1][1])), math.degrees(x),
            math.degrees(math.atan2(-m[2][0], m[2][2])))


def fk(skeleton, root_pos, angles, orders=None):
    """World (position, rotation) of every joint; angles[name] in channel order."""
    out = {}
    for name, parent, offset, _ in skeleton:
        local = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
        for axis, deg in zip(orders[name] if orders else "ZXY", angles.get(name, (0, 0, 0))):
            local = mul(local, rot(axis, deg))
        ppos, prot = out[parent] if parent else (root_pos, ((1, 0, 0), (0, 1, 0), (0, 0, 1)))
        out[name] = (add(ppos, apply(prot, offset)), mul(prot, local))
    return out


def point(world, joint, local):
    pos, r = world[joint]
    return add(pos, apply(r, local))


def smoothstep(x):
    x = max(0.0, min(1.0, x))
    return x * x * (3 - 2 * x)


# ---- foot trajectory ----
def stance_foot(q):
    """Ankle offset from its flat-foot spot, foot pitch and toe pitch (toes up
    positive) in stance. The foot rotates about the heel, rests flat, then
    rolls over the ball and onto the toe tip; the point it rolls about stays
    put, which is what keeps the foot from sliding."""
    yaw = rot("Y", TOE_OUT)
    if q < FLAT:
        pitch = STRIKE_PITCH * (1 - q / FLAT) ** 2   # lands rotating, settles flat
        return add(apply(yaw, HEEL), apply(mul(yaw, rot("X", -pitch)), HEEL), -1), pitch, pitch
    if q < HEEL_OFF:
        return (0.0, 0.0, 0.0), 0.0, 0.0
    # The roll speeds up, so the foot leaves the ground still rotating.
    pitch = -PUSH_PITCH * ((q - HEEL_OFF) / (TOE_OFF - HEEL_OFF)) ** 2
    toe = -TIP_PITCH * max(0.0, (q - TIP_ON) / (TOE_OFF - TIP_ON)) ** 2
    ball = add(apply(yaw, add(TOE_BASE, TIP)), apply(mul(yaw, rot("X", -toe)), TIP), -1)
    return add(ball, apply(mul(yaw, rot("X", -pitch)), TOE_BASE), -1), pitch, toe


def hermite(p0, m0, p1, m1, s):
    return ((2 * s**3 - 3 * s**2 + 1) * p0 + (s**3 - 2 * s**2 + s) * m0
            + (3 * s**2 - 2 * s**3) * p1 + (s**3 - s**2) * m1)


def foot(q, sign):
    """Ankle target relative to the root's straight-line track, foot pitch
    (None in swing), toe extension and the foot's yaw (degrees, about +Y) for
    the leg on side sign at phase q. FOOT_TURN, set for a curving walk, turns
    the foot against the body's turn."""
    base = (0.0, -HEEL[1], FOOT_AHEAD)   # flat-foot ankle, from the hips at heel strike
    if q <= TOE_OFF:
        off, pitch, toe = stance_foot(q)
        pos, toe = add(base, off), toe - pitch
    else:   # a cubic from toe-off to the next heel strike, velocities matched, plus a lift
        s, span, e = (q - TOE_OFF) / (1 - TOE_OFF), 1 - TOE_OFF, 1e-4
        (a0, b0, t0), (a1, _, _) = stance_foot(TOE_OFF), stance_foot(TOE_OFF - e)
        (c0, _, _), (c1, _, _) = stance_foot(0.0), stance_foot(e)
        start, end = add(base, a0), add(base, add(c0, (0, 0, STRIDE)))
        v0 = [(x - y) / e * span for x, y in zip(a0, a1)]
        v1 = [(y - x) / e * span for x, y in zip(c0, c1)]
        pos = tuple(hermite(start[i], v0[i], end[i], v1[i], s) for i in range(3))
        pos = add(pos, (0, SWING_LIFT * math.sin(math.pi * s) * (1 - s) ** 2, 0))
        pitch, toe = None, (t0 - b0) * max(0.0, 1 - s / TOE_RELAX) ** 2
    target = (sign * (FOOT_TRACK + pos[0]), pos[1], pos[2] - STRIDE * q)
    return (*FOOT_TURN(q, sign, target), pitch, toe) if FOOT_TURN else (target, 0.0, pitch, toe)


def leg_ik(pelvis_rot, hip, target, twist):
    """Hip (z, x, y) and knee flexion that put the ankle on target, for a given
    hip twist. A target out of reach straightens the leg towards it."""
    t = apply(tuple(zip(*pelvis_rot)), add(target, hip, -1))
    d = min(math.sqrt(sum(c * c for c in t)), THIGH + SHIN - 1e-9)
    k = math.pi - math.acos((THIGH**2 + SHIN**2 - d * d) / (2 * THIGH * SHIN))
    v = apply(rot("Y", twist), (0.0, -THIGH - SHIN * math.cos(k), -SHIN * math.sin(k)))
    # Solve Rz(g) Rx(a) v = t: Rx keeps x, so g must carry t's x,y onto v's x.
    r, delta = math.hypot(t[0], t[1]), math.atan2(t[1], t[0])
    g = min((delta + sgn * math.acos(max(-1.0, min(1.0, v[0] / r))) for sgn in (1, -1)),
            key=lambda a: abs(math.remainder(a, 2 * math.pi)))
    w = apply(rot("Z", -math.degrees(g)), t)
    a = math.atan2(w[2], w[1]) - math.atan2(v[2], v[1])
    return (math.degrees(math.remainder(g, 2 * math.pi)),
            math.degrees(math.remainder(a, 2 * math.pi)), twist), math.degrees(k)


# ---- pelvis ----
def pelvis(p):
    """Root sideways offset, roll and yaw at phase p."""
    sway = SWAY * math.sin(2 * math.pi * (p - 0.05))   # drifts over the stance foot
    roll = ROLL * math.cos(2 * math.pi * (p - 0.2))    # swing-side hip drops after loading
    yaw = -YAW * math.cos(2 * math.pi * p)             # leading hip forward at heel strike
    return sway, roll, yaw


def eased(keys, q):
    """Periodic keyframe curve with cosine easing between keys."""
    pts = keys + [(keys[0][0] + 1.0, keys[0][1])]
    for (p0, v0), (p1, v1) in zip(pts, pts[1:]):
        if p0 <= q <= p1:
            return v0 + (v1 - v0) * (1 - math.cos(math.pi * (q - p0) / (p1 - p0))) / 2
    raise ValueError(q)


def required_height(p):
    """Highest root that gives each stance leg its STANCE_KNEE bend and lets
    a swing leg reach its target with the knee nearly straight."""
    sway, roll, yaw = pelvis(p)
    best = math.inf
    for sign, shift in ((1, 0.0), (-1, 0.5)):
        q = (p + shift) % 1.0
        knee = eased(STANCE_KNEE, q) if q <= TOE_OFF else STANCE_KNEE[0][1]
        reach = 2 * THIGH * math.cos(math.radians(knee) / 2)   # equal-length bones
        h = apply(zxy(roll, 0, yaw), (sign * HIP[0], HIP[1], HIP[2]))
        t = foot(q, sign)[0]
        dx, dz = t[0] - sway - h[0], t[2] - h[2]
        best = min(best, t[1] - h[1] + math.sqrt(reach**2 - dx * dx - dz * dz))
    return best


_HEIGHTS = []


def root_height(p, n=CYCLE_FRAMES * 10):
    """required_height() eroded (minimum over a window), then averaged over
    the same window: smooth, yet never higher than the legs allow."""
    if not _HEIGHTS:
        raw = [required_height(i / n) for i in range(n)]
        w = round(HEIGHT_SMOOTHING * n)
        low = [min(raw[(i + d) % n] for d in range(-w, w + 1)) for i in range(n)]
        kernel = [(1 + math.cos(math.pi * d / (w + 1)), d) for d in range(-w, w + 1)]
        total = sum(c for c, _ in kernel)
        _HEIGHTS.extend(sum(c * low[(i + d) % n] for c, d in kernel) / total for i in range(n))
    x = (p % 1.0) * n
    i = math.floor(x)
    return _HEIGHTS[i % n] + (_HEIGHTS[(i + 1) % n] - _HEIGHTS[i % n]) * (x - i)


# ---- poses ----
def solve_leg(p, side, sign, shift):
    """Hip, knee, ankle and toe angles of one leg at cycle phase p."""
    q = (p + shift) % 1.0
    sway, roll, yaw = pelvis(p)
    rp = zxy(roll, 0, yaw)
    hip = add((sway, root_height(p), 0.0), apply(rp, (sign * HIP[0], HIP[1], HIP[2])))
    target, turn, pitch, toe = foot(q, sign)
    thigh, knee = leg_ik(rp, hip, target, turn - yaw)   # -yaw: knee faces ahead
    out = {side + "UpLeg": thigh, side + "Leg": (0, knee, 0), side + "ToeBase": (0, -toe, 0)}
    if pitch is not None:   # stance: the foot takes the pitch of its roll
        shin = mul(mul(rp, zxy(*thigh)), rot("X", knee))
        want = mul(rot("Y", turn + sign * TOE_OUT), rot("X", -pitch))
        out[side + "Foot"] = euler_zxy(mul(tuple(zip(*shin)), want))
        return out
    # Swing: the ankle returns to neutral early (toe clearance) and sets up the
    # heel strike late. Blending between the toe-off and heel-strike angles
    # keeps both ends continuous; `carry` continues the toe-off rotation.
    s, e = (q - TOE_OFF) / (1 - TOE_OFF), 1e-4
    start = solve_leg(p - (q - TOE_OFF), side, sign, shift)[side + "Foot"]
    before = solve_leg(p - (q - TOE_OFF) - e, side, sign, shift)[side + "Foot"]
    end = solve_leg(p + (1 - q), side, sign, shift)[side + "Foot"]
    e1, e2, blend = smoothstep(s / 0.35), smoothstep((s - 0.6) / 0.4), smoothstep(s)
    carry = (start[1] - before[1]) / e * (1 - TOE_OFF) * s * max(0.0, 1 - s / 0.35) ** 2
    out[side + "Foot"] = (start[0] + (end[0] - start[0]) * blend,
                          start[1] * (1 - e1) + end[1] * e2 + SWING_ANKLE * (e1 - e2) + carry,
                          start[2] + (end[2] - start[2]) * blend)
    return out


def pose(frame):
    """Root position and per-joint (Z, X, Y) angles for one frame."""
    p = (frame % CYCLE_FRAMES) / CYCLE_FRAMES   # the last frame repeats the first exactly
    sway, roll, yaw = pelvis(p)
    a = {"Hips": (roll, 0, yaw)}
    for side, sign, shift in (("Left", 1, 0.0), ("Right", -1, 0.5)):
        a.update(solve_leg(p, side, sign, shift))
        # Arms swing with the opposite leg, lagging it slightly.
        fwd = -sign * math.cos(2 * math.pi * (p - 0.03))   # +1: this arm furthest forward
        a[side + "Shoulder"] = (-sign * 4, 0, -sign * 2 * fwd)
        a[side + "Arm"] = (-sign * ARM_DOWN, 0, -sign * ARM_SWING * fwd)
        a[side + "ForeArm"] = (0, 0, -sign * (ELBOW + 8 * fwd))   # more bend when forward
        a[side + "Hand"] = (-sign * 8, 0, 0)                      # relaxed, fingers curled
        a[side + "FingerBase"] = (-sign * 15, 0, 0)
        a[side + "HandIndex1"] = (-sign * 20, 0, 0)
    thorax_yaw = -0.75 * yaw                   # shoulders counter-rotate the pelvis
    twist = (thorax_yaw - yaw) / 3
    a["LowerBack"] = (-0.6 * roll, LEAN / 2, twist)   # the spine also undoes pelvis roll
    a["Spine"] = (-0.4 * roll, LEAN / 2, twist)
    a["Spine1"] = (0, 0, twist)
    # The neck cancels lean and twist so the head stays level and looks ahead.
    a["Neck"] = a["Neck1"] = (0, -LEAN / 2, -thorax_yaw / 2)
    return (sway, root_height(p), STRIDE * frame / CYCLE_FRAMES), a


# ---- measuring, writing, checking ----
def sole_points(world, side):
    return [point(world, side + "Foot", HEEL), point(world, side + "ToeBase", BALL),
            point(world, side + "ToeBase", TIP)]


def foot_metrics(worlds):
    """Worst stance slip per step (cm), worst stance hover, lowest sole point,
    from the worlds (fk() per frame, Y up) of a clip that starts at phase 0.
    In each stance frame the lowest sole point is the contact, and its
    horizontal travel to the next frame is slip; rolling from heel to toe
    changes which point is lowest, which is not slip."""
    soles = {s: [sole_points(w, s) for w in worlds] for s in ("Left", "Right")}
    slips, hover = [0.0], 0.0
    n = int(TOE_OFF * CYCLE_FRAMES)
    for side, start in (("Left", 0), ("Right", CYCLE_FRAMES // 2)):
        for first in range(start, len(worlds) - n, CYCLE_FRAMES):
            slips.append(0.0)
            for f in range(first, first + n):
                i = min(range(3), key=lambda k: soles[side][f][k][1])
                p0, p1 = soles[side][f][i], soles[side][f + 1][i]
                slips[-1] += math.hypot(p1[0] - p0[0], p1[2] - p0[2])
                hover = max(hover, p0[1])
    lowest = min(pt[1] for s in soles for pts in soles[s] for pt in pts)
    return max(slips), hover, lowest


def standing_height(skeleton):
    rest = fk(skeleton, (0, 0, 0), {})
    head_end = next(r[3] for r in skeleton if r[0] == "Head")
    return point(rest, "Head", head_end)[1] - min(p[1] for p in sole_points(rest, "Left"))


def write_bvh(path, frames, skeleton=SKELETON, channels=None):
    """frames: (root position, {joint: channel values after the root's
    position}); channels: {joint: channel names} where not the default
    (rotations Zrotation Xrotation Yrotation, and the root's position first)."""
    out = ["HIERARCHY"]

    def emit(name, parent, offset, end, ind):
        default = ("" if parent else "Xposition Yposition Zposition ") + "Zrotation Xrotation Yrotation"
        listed = (channels or {}).get(name, default)
        out.extend([f"{ind}{'JOINT' if parent else 'ROOT'} {name}", ind + "{",
                    f"{ind}  OFFSET {offset[0]:.4f} {offset[1]:.4f} {offset[2]:.4f}",
                    f"{ind}  CHANNELS {len(listed.split())} {listed}"])
        for row in skeleton:
            if row[1] == name:
                emit(*row, ind + "  ")
        if end:
            out.extend([f"{ind}  End Site", ind + "  {",
                        f"{ind}    OFFSET {end[0]:.4f} {end[1]:.4f} {end[2]:.4f}", ind + "  }"])
        out.append(ind + "}")

    emit(*skeleton[0], "")
    out += ["MOTION", f"Frames: {len(frames)}", f"Frame Time: {1 / FPS:.7f}"]
    for root, a in frames:
        values = list(root) + [v for name, *_ in skeleton for v in a.get(name, (0, 0, 0))]
        # "+ 0.0" and the replace keep "-0.0000" out of the file
        out.append(" ".join(f"{v + 0.0:.4f}".replace("-0.0000", "0.0000") for v in values))
    with open(path, "w", newline="\n") as fh:
        fh.write("\n".join(out) + "\n")


VARIANTS_HELP = __doc__[__doc__.index("A variant needs"):]


def main():
    # walk_variants imports this file as a module: let it find this running copy.
    sys.modules.setdefault("make_walk_bvh", sys.modules[__name__])
    import walk_variants as wv
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0], epilog=VARIANTS_HELP,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    # Default relative to the repository, so running from elsewhere leaves no stray copies.
    default_out = os.path.relpath(
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "walk.bvh"))
    ap.add_argument("--out", help=f"BVH file to write (default {default_out}, the project's clip)")
    ap.add_argument("--check", action="store_true", help="re-read the written file and verify it")
    ap.add_argument("--speed", type=float, default=wv.SPEED, metavar="M_PER_S",
                    help="ground speed, 0.2-1.6: the stride scales, the 1.1 s cycle stays "
                    "(default 1.3)")
    ap.add_argument("--turn-rate", type=float, default=0.0, metavar="DEG_PER_S",
                    help="walk a circle at this mean yaw rate, within +-90; positive turns left "
                    "(+Z towards +X)")
    ap.add_argument("--static-root", action="store_true",
                    help="a zero ROOT joint_Root above Hips, which gets 6 channels and the motion")
    ap.add_argument("--up", choices=("y", "z", "x"), default="y",
                    help="the file's up axis: z rotates the capture +90 deg about X, x -90 about Z")
    ap.add_argument("--cycles", type=int, default=CYCLES, metavar="N",
                    help=f"gait cycles: N x {CYCLE_FRAMES} + 1 frames (default {CYCLES})")
    ap.add_argument("--frames", type=int, metavar="N", help="write exactly the first N frames")
    ap.add_argument("--suite", metavar="DIR", help="write the acceptance-test clips and "
                    "known_answers.json into DIR and check each (other options ignored)")
    args = ap.parse_args()
    if args.suite:
        sys.exit(0 if wv.write_suite(args.suite) else 1)
    options = {"speed": args.speed, "turn_rate": args.turn_rate, "static_root": args.static_root,
               "up": args.up, "cycles": args.cycles, "frames": args.frames}
    if options != {"speed": wv.SPEED, "turn_rate": 0.0, "static_root": False, "up": "y",
                   "cycles": CYCLES, "frames": None} and not args.out:
        ap.error(f"a variant needs --out: {default_out} is the project's default clip")
    if not wv.SPEED_RANGE[0] <= args.speed <= wv.SPEED_RANGE[1]:
        ap.error(f"--speed must be within {wv.SPEED_RANGE[0]}-{wv.SPEED_RANGE[1]} m/s")
    if abs(args.turn_rate) > wv.MAX_TURN:
        ap.error(f"--turn-rate must be within +-{wv.MAX_TURN:g} deg/s")
    if args.cycles < 1 or (args.frames is not None and args.frames < 1):
        ap.error("--cycles and --frames must be at least 1")
    out = args.out or default_out
    clip = wv.build(**options)
    write_bvh(out, clip["frames"], clip["skeleton"], clip["channels"])
    slip = foot_metrics(clip["reference"])[0]
    print(f"{out}: {len(clip['skeleton'])} joints, {len(clip['frames'])} frames at {FPS} fps "
          f"({CYCLE_FRAMES / FPS:.2f} s cycles, {args.speed:.2f} m/s, {args.turn_rate:g} deg/s, "
          f"{args.up} up), height {standing_height(SKELETON):.1f} cm, max stance-foot slip "
          f"{slip:.2f} cm/step")
    if args.check and not wv.check(out, clip):
        sys.exit(1)


if __name__ == "__main__":
    main()
