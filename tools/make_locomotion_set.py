#!/usr/bin/env python3
"""Write the rest of Throng's own locomotion set beside assets/walk.bvh: an
idle, a slow walk and a run on the walk's 31-joint skeleton, as BVH.

Usage: tools/make_locomotion_set.py [--dir assets] [--check]

The default crowd blends these clips by speed (issue #12), so the engine needs
no outside files for it. Output is deterministic; the clips are CC0 (see
assets/LICENSE.md). Each gait is tools/make_walk_bvh.py's walk with other
parameters (cycle, stride, foot timeline, knee, pelvis and arm swing): the
feet follow a planted heel-to-toe roll in stance and the legs are solved from
it, so stance feet stay planted at every speed.

  idle.bvh       standing: weight shifts from foot to foot, breathing and a
                 slow look around, both feet flat and still (4 s loop)
  slow_walk.bvh  0.80 m/s: 1.30 s cycle, 104 cm stride, flatter heel strike
  walk.bvh       1.30 m/s: 1.10 s cycle, 143 cm stride (make_walk_bvh.py)
  run.bvh        2.80 m/s: 0.70 s cycle, 196 cm stride, stance 36% of the
                 cycle, so both feet are off the ground twice a cycle (flight)

Every gait starts at the left heel strike and is two cycles long plus the
closing frame. --check re-reads each file and verifies it the way
make_walk_bvh.py --check does (joints where the generator put them, loop
closed, arc speed, soles on the ground, stance slip), and that the idle's
feet never move.
"""
import argparse
import math
import os
import sys

import make_walk_bvh as mw
import walk_variants as wv

# Gait parameters, as make_walk_bvh's module constants: name -> value. Values
# not listed keep the default walk's.
SLOW_WALK = {
    "CYCLE_FRAMES": 78, "STRIDE": 104.0, "FOOT_AHEAD": 24.0,
    "STRIKE_PITCH": 14.0, "PUSH_PITCH": 55.0, "TIP_PITCH": 20.0, "SWING_LIFT": 10.0,
    "TOE_OFF": 0.63, "TIP_ON": 0.50, "HEEL_OFF": 0.34,
    "SWAY": 2.6, "ROLL": 2.0, "YAW": 3.0, "LEAN": 2.0,
    "ARM_SWING": 9.0, "ELBOW": 12.0,
}
RUN = {
    "CYCLE_FRAMES": 42, "STRIDE": 196.0, "FOOT_AHEAD": 30.0,
    "FLAT": 0.05, "HEEL_OFF": 0.17, "TIP_ON": 0.27, "TOE_OFF": 0.36,
    "STRIKE_PITCH": 10.0, "PUSH_PITCH": 55.0, "TIP_PITCH": 25.0,
    "SWING_LIFT": 34.0, "SWING_ANKLE": -8.0,
    "STANCE_KNEE": [(0.0, 16.0), (0.12, 38.0), (0.36, 22.0)],
    "SWAY": 1.0, "ROLL": 4.0, "YAW": 7.0, "LEAN": 9.0,
    "ARM_DOWN": 70.0, "ARM_SWING": 30.0, "ELBOW": 80.0,
}
GAITS = [("slow_walk.bvh", SLOW_WALK), ("run.bvh", RUN)]
IDLE_FRAMES = 240          # 4 s loop at 60 fps
STANCE_WIDTH = 10.0        # idle ankles at x = +-10 cm
IDLE_KNEE = 6.0            # degrees of knee bend standing


def gait_speed(params):
    """Ground speed in m/s of a gait: stride per cycle."""
    return params["STRIDE"] / 100 / (params["CYCLE_FRAMES"] / mw.FPS)


class Gait:
    """Sets make_walk_bvh's parameters for the gait and restores them on exit."""

    def __init__(self, params):
        self.params, self.saved = params, {}

    def __enter__(self):
        for name, value in self.params.items():
            self.saved[name] = getattr(mw, name)
            setattr(mw, name, value)
        mw._HEIGHTS.clear()   # the pelvis heights depend on the gait
        return self

    def __exit__(self, *_):
        for name, value in self.saved.items():
            setattr(mw, name, value)
        mw._HEIGHTS.clear()


def answers(speed, count, cycle_frames):
    return {"arc_speed_m_per_s": round(speed, 6), "turn_rate_deg_per_s": 0.0,
            "stature_m": round(mw.standing_height(mw.SKELETON) / 100, 4), "up_axis": "y",
            "frame_count": count, "cycle_s": round(cycle_frames / mw.FPS, 4)}


def build_gait(params):
    """A gait's frames (root, angles), two cycles plus the closing frame."""
    count = 2 * mw.CYCLE_FRAMES + 1
    rows = [mw.pose(f) for f in range(count)]
    return {"skeleton": mw.SKELETON, "channels": {"Hips": wv.POSITIONS + wv.rotations("ZXY")},
            "frames": rows, "reference": [mw.fk(mw.SKELETON, r, a) for r, a in rows],
            "up": wv.IDENTITY, "answers": answers(gait_speed(params), count, mw.CYCLE_FRAMES)}


# ---- idle ----
def idle_pose(frame):
    """Standing: the pelvis shifts over one foot then the other, the chest
    breathes, the head looks slowly left and right; feet flat and fixed."""
    p = (frame % IDLE_FRAMES) / IDLE_FRAMES
    shift = math.sin(2 * math.pi * p)                  # +1: weight over the left foot
    breath = math.sin(2 * math.pi * 2 * p)
    sway, roll, yaw = 2.5 * shift, -1.5 * shift, 2.0 * math.sin(2 * math.pi * p + 1.0)
    rp = mw.zxy(roll, 0, yaw)
    ankles = {sign: (sign * STANCE_WIDTH, -mw.HEEL[1], 0.0) for sign in (1, -1)}
    # The highest pelvis at which both legs keep at least IDLE_KNEE of bend.
    reach = 2 * mw.THIGH * math.cos(math.radians(IDLE_KNEE) / 2)
    height = math.inf
    for sign, ankle in ankles.items():
        h = mw.apply(rp, (sign * mw.HIP[0], mw.HIP[1], mw.HIP[2]))
        dx, dz = ankle[0] - sway - h[0], ankle[2] - h[2]
        height = min(height, ankle[1] - h[1] + math.sqrt(reach**2 - dx * dx - dz * dz))
    a = {"Hips": (roll, 0, yaw)}
    for side, sign in (("Left", 1), ("Right", -1)):
        hip = mw.add((sway, height, 0.0), mw.apply(rp, (sign * mw.HIP[0], mw.HIP[1], mw.HIP[2])))
        thigh, knee = mw.leg_ik(rp, hip, ankles[sign], -yaw)
        shin = mw.mul(mw.mul(rp, mw.zxy(*thigh)), mw.rot("X", knee))
        flat = mw.rot("Y", sign * mw.TOE_OUT)
        a[side + "UpLeg"], a[side + "Leg"] = thigh, (0, knee, 0)
        a[side + "Foot"] = mw.euler_zxy(mw.mul(tuple(zip(*shin)), flat))
        a[side + "Shoulder"] = (-sign * 4, 0, 0)
        a[side + "Arm"] = (-sign * (mw.ARM_DOWN + 5 + 1.0 * breath), 0, sign * 3)
        a[side + "ForeArm"] = (0, 0, -sign * 12)
        a[side + "Hand"] = (-sign * 8, 0, 0)
        a[side + "FingerBase"] = (-sign * 15, 0, 0)
        a[side + "HandIndex1"] = (-sign * 20, 0, 0)
    look = 12.0 * math.sin(2 * math.pi * p + 0.5)
    a["LowerBack"] = (-0.6 * roll, 0.5 + 0.6 * breath, -yaw / 2)
    a["Spine"] = (-0.4 * roll, 0.5 + 0.6 * breath, -yaw / 2)
    a["Spine1"] = (0, -0.8 * breath, 0)
    a["Neck"] = a["Neck1"] = (0, -0.3 * breath, look / 2)
    return (sway, height, 0.0), a


def build_idle():
    count = IDLE_FRAMES + 1
    rows = [idle_pose(f) for f in range(count)]
    return {"skeleton": mw.SKELETON, "channels": {"Hips": wv.POSITIONS + wv.rotations("ZXY")},
            "frames": rows, "reference": [mw.fk(mw.SKELETON, r, a) for r, a in rows],
            "up": wv.IDENTITY, "answers": answers(0.0, count, IDLE_FRAMES)}


def check_idle(path, clip):
    """Joints where the generator put them, loop closed, feet flat and still."""
    skeleton, channels, n_frames, rows = wv.read_bvh(path)
    worlds = [wv.file_worlds(skeleton, channels, r, wv.IDENTITY) for r in rows]
    err = max(math.dist(w[n][0], ref[n][0]) for w, ref in zip(worlds, clip["reference"])
              for n, *_ in mw.SKELETON)
    seam = max(math.dist(worlds[0][n][0], worlds[-1][n][0]) for n, *_ in mw.SKELETON)
    soles = [p for w in worlds for s in ("Left", "Right") for p in mw.sole_points(w, s)]
    drift = max(math.dist(mw.sole_points(w, s)[k], mw.sole_points(worlds[0], s)[k])
                for w in worlds for s in ("Left", "Right") for k in range(3))
    low, high = min(p[1] for p in soles), max(p[1] for p in soles)
    checks = [("joints where the generator put them", err < 0.01, f"within {err:.4f} cm"),
              ("loop closed", seam < 0.01, f"last frame {seam:.4f} cm from the first"),
              ("feet still", drift < 0.05, f"sole points move at most {drift:.4f} cm"),
              ("soles on the ground", -1.0 < low and high < 2.5, f"sole heights {low:.2f}-{high:.2f} cm")]
    print(f"check {path}:")
    for label, good, detail in checks:
        print(f"  {'ok  ' if good else 'FAIL'} {label}: {detail}")
    return all(good for _, good, _ in checks) and n_frames == len(clip["frames"])


def main():
    sys.modules.setdefault("make_locomotion_set", sys.modules[__name__])
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0], epilog=__doc__.split("\n\n", 1)[1],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    default_dir = os.path.relpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets"))
    ap.add_argument("--dir", default=default_dir, help=f"where to write the clips (default {default_dir})")
    ap.add_argument("--check", action="store_true", help="re-read each written file and verify it")
    args = ap.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    ok = True
    for name, params in GAITS:
        with Gait(params):
            clip = build_gait(params)
            path = os.path.join(args.dir, name)
            mw.write_bvh(path, clip["frames"], clip["skeleton"], clip["channels"])
            slip = mw.foot_metrics(clip["reference"])[0]
            print(f"{path}: {len(clip['frames'])} frames, {gait_speed(params):.2f} m/s, "
                  f"{mw.CYCLE_FRAMES / mw.FPS:.2f} s cycles, max stance-foot slip {slip:.2f} cm/step")
            if args.check:
                ok &= wv.check(path, clip)
    clip = build_idle()
    path = os.path.join(args.dir, "idle.bvh")
    mw.write_bvh(path, clip["frames"], clip["skeleton"], clip["channels"])
    print(f"{path}: {len(clip['frames'])} frames, standing")
    if args.check:
        ok &= check_idle(path, clip)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
