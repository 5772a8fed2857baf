# A TCP sample server that falls silent, for the silent-link end-to-end scripts (silent_link.sh,
# silent_record.sh). Usage: python3 silent_server.py MODE SECONDS
# Prints its port, then for each client: SECONDS of a still sensor (z up, 100 Hz, in counts),
# then nothing (MODE "silent") or lines that are not samples (MODE "nan"), connection held open.
# Gives up 60 s after the last client arrives.
import random, socket, sys, time

mode, seconds = sys.argv[1], float(sys.argv[2])
s = socket.socket()
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("127.0.0.1", 0))
s.listen(4)
print(s.getsockname()[1], flush=True)
s.settimeout(60)
held = []
rng = random.Random(1)
try:
    while True:
        c, _ = s.accept()
        held.append(c)
        try:
            start = time.monotonic()
            k = 0
            while time.monotonic() - start < seconds:
                lines = []
                for _ in range(10):
                    lines.append("%.2f %d %d %d\n" % (k / 100.0, round(2048 + rng.gauss(0, 1.5)),
                                 round(2048 + rng.gauss(0, 1.5)), round(2389 + rng.gauss(0, 1.7))))
                    k += 1
                c.sendall("".join(lines).encode())
                time.sleep(0.1)
            while mode == "nan":
                c.sendall(b"nan nan nan nan\n")
                time.sleep(0.01)
        except OSError:
            pass
except socket.timeout:
    pass
