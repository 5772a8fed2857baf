# A live TCP sample server whose sensor is turned while the wizard waits (issue 27, item 6).
# Usage: python3 pose_server.py CONTROL_FILE
# Prints its port, then streams a still sensor in real time (100 Hz, 10 lines every 0.1 s, in
# counts of the seed procedure's nominal model: 2048 counts at 0 g, 34.8 counts per m/s^2) to
# each client. The pose is the axis named in CONTROL_FILE ("+z", "-z", "+x", ...), read before
# every burst, so the test turns the sensor by writing the file. Its own generator: nothing of
# accelcal is used. Gives up 120 s after the last client arrives.
import random, socket, sys, time

control = sys.argv[1]
G_COUNTS = 34.8 * 9.80665
AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0),
        "+z": (0, 0, 1), "-z": (0, 0, -1)}


def pose():
    try:
        with open(control) as f:
            return AXES.get(f.read().strip(), AXES["+z"])
    except OSError:
        return AXES["+z"]


s = socket.socket()
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("127.0.0.1", 0))
s.listen(4)
print(s.getsockname()[1], flush=True)
s.settimeout(120)
rng = random.Random(3)
try:
    while True:
        c, _ = s.accept()
        start = time.monotonic()
        k = 0
        try:
            while True:
                up = pose()
                lines = []
                for _ in range(10):
                    counts = [round(2048 + G_COUNTS * u + rng.gauss(0, 1.5)) for u in up]
                    lines.append("%.2f %d %d %d\n" % (k / 100.0, counts[0], counts[1], counts[2]))
                    k += 1
                c.sendall("".join(lines).encode())
                # Real time: the next burst when its samples are due.
                time.sleep(max(0.0, start + k / 100.0 - time.monotonic()))
        except OSError:
            c.close()
except socket.timeout:
    pass
