# Two calibrations of the same virtual bench agree within their uncertainty: every one of the nine
# parameters within K combined sigmas (sqrt(s1^2 + s2^2)). The second may be in another unit:
# --scale S --zero B convert its counts to the first's (counts1 = counts2 * S / 1000 + B for a
# MAVLink stream's counts of 0.001 m/s^2 read by a driver (raw - B) / S; scales likewise).
# Usage: python3 same_calibration.py A.json B.json K [--scale S --zero B]
import json, math, sys

a, b = (json.load(open(p)) for p in sys.argv[1:3])
k = float(sys.argv[3])
scale, zero = 1000.0, 0.0
if "--scale" in sys.argv:
    scale = float(sys.argv[sys.argv.index("--scale") + 1])
    zero = float(sys.argv[sys.argv.index("--zero") + 1])
f = scale / 1000.0 if "--scale" in sys.argv else 1.0

def params(c, factor, offset):
    u = c["uncertainty"]
    out = {}
    for j, axis in enumerate("xyz"):
        out["bias_" + axis] = (c["bias_counts"][j] * factor + offset, u["bias_counts"][j] * factor)
        out["scale_" + axis] = (c["scale_counts_per_mps2"][j] * factor, u["scale_counts_per_mps2"][j] * factor)
    for name in ("yz", "zy", "zx"):
        s = u["misalignment_rad"][name]
        out["a_" + name] = (c["misalignment_rad"][name], s if s is not None else 0.0)
    return out

pa, pb = params(a, 1.0, 0.0), params(b, f, zero if "--scale" in sys.argv else 0.0)
worst = 0.0
for name, (va, sa) in pa.items():
    vb, sb = pb[name]
    z = abs(va - vb) / math.sqrt(sa * sa + sb * sb) if sa or sb else (0.0 if va == vb else math.inf)
    worst = max(worst, z)
    print("%-8s %12.6g %12.6g  (%.2f sigma)" % (name, va, vb, z))
print("worst: %.2f sigma (limit %g)" % (worst, k))
sys.exit(0 if worst <= k else 1)
