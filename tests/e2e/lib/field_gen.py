#!/usr/bin/env python3
"""Test files of the shapes loggers in the field write, from the physics alone.

Independent of accelcal's code (the standard library only): the sensor is the lab chapter's
model, raw = K T^-1 f + b with T = [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]] (docs/model.md, "The
model"), f the specific force in the platform frame (|f| = g at rest), white noise per axis,
rounded to whole counts. Each pose is placed with a random small rotation (the hand's error).

  field_gen.py captures --poses six|near40|p11|p12 --seed N -o SET.csv --truth TRUTH.json
      a capture set (accelcal's CSV), one capture per pose, 1000 samples at 100 Hz
  field_gen.py recording --poses near40 --seed N --rate HZ [--style plain|realsense|gyro-first|mpu6050]
      -o FILE --truth TRUTH.json
      a continuous recording: a still start, then each pose held 6 s with 2 s moves between

Styles of recording:
  plain       "t ax ay az" in counts, blanks
  realsense   "t,ax,ay,az" in m/s^2 as the logger converts them with its nominal scale and zero
              (counts_to_mps2 below), t printed with two decimals (at 200 Hz it repeats)
  gyro-first  "t gx gy gz ax ay az" (a header row naming them), gyro noise in rad/s
  mpu6050     Arduino-style CSV: key,value metadata lines, the header "ax,ay,az,gx,gy,gz", signed
              16-bit counts (+-2 g: 16384 counts per g), no time column (rate given by --rate)

The truth JSON holds the sensor in counts ("bias_counts", "scale_counts_per_mps2",
"misalignment_rad") and, for the realsense style, "logger": its nominal zero and scale, with the
truth in the logger's m/s^2 taken as counts of 0.001 m/s^2 ("bias_mcounts", "scale_mcounts").
"""
import argparse
import json
import math
import random

G = 9.80665

SENSORS = {
    # A 12-bit unsigned ADC reading an MMA7260Q-like part at +-6 g (the bench's default).
    "mma7260": dict(bias=[2051.3, 2039.6, 2062.8], scale=[34.62, 35.07, 34.41],
                    mis=[0.0042, -0.0031, 0.0057], noise=[1.5, 1.5, 1.7], lo=0, hi=4095),
    # An MPU-6050 at +-2 g: signed 16-bit, 16384 counts per g nominal.
    "mpu6050": dict(bias=[-312.0, 145.0, 418.0], scale=[1668.2, 1673.9, 1661.5],
                    mis=[0.0061, -0.0044, 0.0029], noise=[18.0, 18.0, 26.0], lo=-32768, hi=32767),
}


def six_faces():
    return [(0, 0, 1), (0, 0, -1), (1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0)]


def poses(name, rng):
    if name == "six":
        return six_faces()
    if name == "p11":  # six faces and five tilted poses
        return six_faces() + [(1, 1, 1), (1, 1, -1), (1, -1, 1), (-1, 1, 1), (1, -1, -1)]
    if name == "p12":
        return six_faces() + [(1, 1, 1), (1, 1, -1), (1, -1, 1), (-1, 1, 1), (1, -1, -1), (-1, -1, 1)]
    if name == "near40":
        # Hand-placed near the six faces: each face several times, tilted 2 to 9 deg off it in
        # a random direction (the poses imu_tk's users take by hand).
        out = []
        faces = six_faces()
        for i in range(40):
            face = faces[i % 6]
            tilt = math.radians(rng.uniform(2.0, 9.0))
            phi = rng.uniform(0.0, 2.0 * math.pi)
            # Two directions perpendicular to the face.
            a = [1.0, 0.0, 0.0] if face[0] == 0 else [0.0, 1.0, 0.0]
            b = cross(face, a)
            v = [math.cos(tilt) * face[k] + math.sin(tilt) * (math.cos(phi) * a[k] + math.sin(phi) * b[k])
                 for k in range(3)]
            out.append(tuple(v))
        return out
    raise SystemExit("unknown pose set " + name)


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def normalized(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def small_rotation(v, sigma_rad, rng):
    """v turned by a random small rotation (each component of the rotation vector ~ N(0, s))."""
    w = [rng.gauss(0.0, sigma_rad) for _ in range(3)]
    angle = math.sqrt(sum(x * x for x in w))
    if angle == 0.0:
        return list(v)
    k = [x / angle for x in w]
    c, s = math.cos(angle), math.sin(angle)
    kv = cross(k, v)
    kdv = sum(k[i] * v[i] for i in range(3))
    return [v[i] * c + kv[i] * s + k[i] * kdv * (1 - c) for i in range(3)]


def raw_mean(sensor, f):
    """raw = K T^-1 f + b (no noise)."""
    a_yz, a_zy, a_zx = sensor["mis"]
    # T^-1 of T = [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]]: back substitution.
    z = f[2]
    y = f[1] + a_zx * z
    x = f[0] + a_yz * y - a_zy * z
    u = [x, y, z]
    return [sensor["scale"][j] * u[j] + sensor["bias"][j] for j in range(3)]


def reading(sensor, mean, rng):
    out = []
    for j in range(3):
        v = round(mean[j] + rng.gauss(0.0, sensor["noise"][j]))
        out.append(min(max(v, sensor["lo"]), sensor["hi"]))
    return out


def truth_json(sensor):
    return {"bias_counts": sensor["bias"], "scale_counts_per_mps2": sensor["scale"],
            "misalignment_rad": {"yz": sensor["mis"][0], "zy": sensor["mis"][1], "zx": sensor["mis"][2]}}


def write_captures(args, rng):
    sensor = SENSORS[args.sensor]
    lines = ["# field_gen.py captures --poses %s --seed %d" % (args.poses, args.seed),
             "capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up"]
    t = 0.0
    for i, up in enumerate(poses(args.poses, rng)):
        up = normalized(up)
        placed = small_rotation(up, math.radians(args.placement_deg), rng)
        mean = raw_mean(sensor, [G * x for x in placed])
        up_text = " ".join("%.6f" % x for x in up)
        for n in range(args.samples):
            r = reading(sensor, mean, rng)
            lines.append("%d,static,%.2f,%d,%d,%d,,,,pose %d,%s" % (i + 1, t, r[0], r[1], r[2], i + 1, up_text))
            t += 0.01
        t += 20.0
    with open(args.output, "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(args.truth, "w") as f:
        json.dump(truth_json(sensor), f, indent=1)


# The realsense-style logger's own conversion of its counts to m/s^2 (nominal zero and scale).
LOGGER_ZERO = 2048.0
LOGGER_SCALE = 34.8


def write_recording(args, rng):
    sensor = SENSORS["mpu6050" if args.style == "mpu6050" else args.sensor]
    rate = args.rate
    rows = []  # (t, counts)
    t = 0.0
    pose_list = [normalized(p) for p in poses(args.poses, rng)]
    current = small_rotation(pose_list[0], math.radians(args.placement_deg), rng)

    def hold(direction, seconds):
        nonlocal t
        mean = raw_mean(sensor, [G * x for x in direction])
        for _ in range(int(round(seconds * rate))):
            rows.append((t, reading(sensor, mean, rng)))
            t += 1.0 / rate

    hold(current, args.still_s)
    for p in pose_list[1:]:
        target = small_rotation(p, math.radians(args.placement_deg), rng)
        # The move: turned through intermediate directions, shaken by the hand.
        steps = int(round(2.0 * rate))
        for k in range(steps):
            w = (k + 1) / steps
            d = normalized([(1 - w) * current[i] + w * target[i] + rng.gauss(0, 0.05) for i in range(3)])
            mean = raw_mean(sensor, [G * x * (1 + rng.gauss(0, 0.1)) for x in d])
            rows.append((t, reading(sensor, mean, rng)))
            t += 1.0 / rate
        current = target
        hold(current, args.hold_s)

    truth = truth_json(sensor)
    out = []
    if args.style == "plain":
        out = ["%.6f %d %d %d" % (tt, r[0], r[1], r[2]) for tt, r in rows]
    elif args.style == "realsense":
        out = ["t,ax,ay,az"]
        for tt, r in rows:
            a = [(r[j] - LOGGER_ZERO) / LOGGER_SCALE for j in range(3)]
            out.append("%.2f,%.4f,%.4f,%.4f" % (tt, a[0], a[1], a[2]))
        truth["logger"] = {"zero_counts": LOGGER_ZERO, "scale_counts_per_mps2": LOGGER_SCALE}
        truth["bias_mcounts"] = [(b - LOGGER_ZERO) / LOGGER_SCALE * 1000 for b in sensor["bias"]]
        truth["scale_mcounts"] = [k / LOGGER_SCALE * 1000 for k in sensor["scale"]]
    elif args.style == "gyro-first":
        out = ["t gx gy gz ax ay az"]
        for tt, r in rows:
            g = [rng.gauss(0, 0.002) for _ in range(3)]
            out.append("%.5f %.5f %.5f %.5f %d %d %d" % (tt, g[0], g[1], g[2], r[0], r[1], r[2]))
    elif args.style == "mpu6050":
        out = ["sketch,MPU6050_raw", "accel_range_g,2", "gyro_range_dps,250", "rate_hz,%g" % rate,
               "ax,ay,az,gx,gy,gz"]
        for _, r in rows:
            g = [int(round(rng.gauss(0, 4))) for _ in range(3)]
            out.append("%d,%d,%d,%d,%d,%d" % (r[0], r[1], r[2], g[0], g[1], g[2]))
    with open(args.output, "w") as f:
        f.write("\n".join(out) + "\n")
    with open(args.truth, "w") as f:
        json.dump(truth, f, indent=1)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("what", choices=["captures", "recording"])
    p.add_argument("--poses", default="six")
    p.add_argument("--sensor", default="mma7260", choices=sorted(SENSORS))
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--samples", type=int, default=1000)
    p.add_argument("--placement-deg", type=float, default=0.5)
    p.add_argument("--rate", type=float, default=100.0)
    p.add_argument("--still-s", type=float, default=60.0)
    p.add_argument("--hold-s", type=float, default=6.0)
    p.add_argument("--style", default="plain", choices=["plain", "realsense", "gyro-first", "mpu6050"])
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--truth", required=True)
    args = p.parse_args()
    rng = random.Random(args.seed)
    if args.what == "captures":
        write_captures(args, rng)
    else:
        write_recording(args, rng)


if __name__ == "__main__":
    main()
