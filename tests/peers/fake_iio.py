# A fake Linux IIO device fed from the virtual bench: a directory laid out as the kernel's sysfs
# tree (Documentation/ABI/testing/sysfs-bus-iio) and a FIFO standing in for /dev/iio:deviceN.
# Written from the ABI's description, sharing nothing with accelcal's reader: the record layout
# (each element aligned to its own size, the record padded to its largest) and the packing of
# the scan types are done here on their own.
#
# Sample lines `t ax ay az [temp_c]` (counts) come on stdin (`accelcal record --source sim -o -`).
#   buffer mode: waits for buffer/enable (or buffer0/enable) to read 1, reads which scan elements
#     are enabled (in_*_en), and writes one record per line to the FIFO: the counts packed by
#     --type, the timestamp channel in ns from t. While no reader has the FIFO open, lines are
#     dropped (a live sensor does not wait); a reader that goes away is waited for again.
#   poll mode: no buffer; each line is written to the in_*_raw files (atomically, by rename).
# Faults: --eio-after S (in_<y>_raw then reads -EIO: a link to /proc/self/mem, which fails with
# EIO at offset 0), --vanish-after S (the device directory removed, the FIFO closed: a device
# unplugged), --skip-every N (every Nth record not written: the timestamps jump, an overrun).
#
# Usage: python3 fake_iio.py ROOT [--name adxl345] [--id 0] [--layout buffer0|buffer|none]
#          [--type le:s12/16>>4] [--channels accel_x,accel_y,accel_z] [--extra voltage3]
#          [--scale 0.038307] [--no-timestamp] [--offset-counts N] [--fifo PATH] ...
# Prints "ready" once the tree exists.
import argparse, errno, os, re, select, shutil, stat, struct, sys, time

ap = argparse.ArgumentParser()
ap.add_argument("root")
ap.add_argument("--name", default="adxl345")
ap.add_argument("--id", type=int, default=0)
ap.add_argument("--layout", default="buffer0", choices=["buffer0", "buffer", "none"])
ap.add_argument("--type", default="le:s12/16>>4")
ap.add_argument("--channels", default="accel_x,accel_y,accel_z")
ap.add_argument("--extra", default="", help="another channel with a scan element, left disabled")
ap.add_argument("--scale", default="0.038307")
ap.add_argument("--offset-counts", default=None)
ap.add_argument("--no-timestamp", action="store_true")
ap.add_argument("--fifo", default=None)
ap.add_argument("--rate", default="100")
ap.add_argument("--trigger", default=None)
ap.add_argument("--eio-after", type=float, default=None)
ap.add_argument("--vanish-after", type=float, default=None)
ap.add_argument("--skip-every", type=int, default=0)
ap.add_argument("--bias", type=float, default=0.0, help="subtracted from the counts (signed types)")
a = ap.parse_args()

dev = os.path.join(a.root, "iio:device%d" % a.id)
channels = a.channels.split(",")
kind = channels[0].split("_")[0].rstrip("0123456789")


def put(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("%s\n" % text)
    os.replace(tmp, path)


def get(path):
    try:
        with open(path) as f:
            return f.read().strip()
    except OSError:
        return ""


def parse_type(text):
    m = re.fullmatch(r"(le|be):([su])(\d+)/(\d+)(?:X(\d+))?>>(\d+)", text)
    if not m:
        return None
    return dict(be=m.group(1) == "be", signed=m.group(2) == "s", bits=int(m.group(3)),
                storage=int(m.group(4)), repeat=int(m.group(5) or 1), shift=int(m.group(6)))


def pack(value, t):
    nbytes = t["storage"] // 8
    v = int(round(value))
    lo, hi = (-(1 << (t["bits"] - 1)), (1 << (t["bits"] - 1)) - 1) if t["signed"] else (0, (1 << t["bits"]) - 1)
    v = max(lo, min(hi, v)) & ((1 << t["bits"]) - 1)
    return (v << t["shift"]).to_bytes(nbytes, "big" if t["be"] else "little")


# ---- the tree ----
shutil.rmtree(dev, ignore_errors=True)
put(os.path.join(dev, "name"), a.name)
put(os.path.join(dev, "in_%s_scale" % kind), a.scale)
if a.offset_counts is not None:
    put(os.path.join(dev, "in_%s_offset" % kind), a.offset_counts)
put(os.path.join(dev, "sampling_frequency"), a.rate)
put(os.path.join(dev, "sampling_frequency_available"), "25 50 100 200 400")
put(os.path.join(dev, "trigger", "current_trigger"), a.trigger if a.trigger is not None else "%s-dev%d" % (a.name, a.id))
for c in channels:
    put(os.path.join(dev, "in_%s_raw" % c), "0")
buffered = a.layout != "none"
scan_dir = os.path.join(dev, "buffer0") if a.layout == "buffer0" else os.path.join(dev, "scan_elements")
buffer_dir = os.path.join(dev, a.layout)
elements = []  # (name, index, type text)
if buffered:
    put(os.path.join(buffer_dir, "enable"), "0")
    put(os.path.join(buffer_dir, "length"), "128")
    put(os.path.join(buffer_dir, "watermark"), "1")
    names = channels + ([a.extra] if a.extra else [])
    for i, c in enumerate(names):
        elements.append((c, i, a.type))
    if not a.no_timestamp:
        elements.append(("timestamp", len(names), "le:s64/64>>0"))
    for name, index, type_text in elements:
        put(os.path.join(scan_dir, "in_%s_en" % name), "0")
        put(os.path.join(scan_dir, "in_%s_index" % name), str(index))
        put(os.path.join(scan_dir, "in_%s_type" % name), type_text)
fifo = a.fifo or os.path.join(a.root, "iio:device%d.fifo" % a.id)
if buffered:
    try:
        os.unlink(fifo)
    except FileNotFoundError:
        pass
    os.mkfifo(fifo)
print("ready", flush=True)


def layout():
    """The enabled elements in index order: (name, offset, type), and the record's size."""
    on = [(n, i, parse_type(t)) for n, i, t in elements if get(os.path.join(scan_dir, "in_%s_en" % n)) == "1"]
    on.sort(key=lambda e: e[1])
    offset, largest, out = 0, 1, []
    for name, _, t in on:
        size = t["storage"] // 8 * t["repeat"]
        offset = (offset + size - 1) // size * size
        out.append((name, offset, t))
        offset += size
        largest = max(largest, size)
    return out, (offset + largest - 1) // largest * largest


writer = None
record_layout, record_size = None, 0
start = time.monotonic()
count = 0
eio_done = False
stdin = sys.stdin.buffer
pending = b""


def open_writer():
    global writer, record_layout, record_size
    if get(os.path.join(buffer_dir, "enable")) != "1":
        return
    try:
        writer = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
    except OSError as e:
        if e.errno == errno.ENXIO:  # nobody reads yet
            return
        raise
    os.set_blocking(writer, True)
    record_layout, record_size = layout()


def write_record(t_s, counts):
    global writer
    rec = bytearray(record_size)
    for name, offset, t in record_layout:
        if name == "timestamp":
            rec[offset:offset + 8] = struct.pack("<q", int(round(t_s * 1e9)))
        else:
            value = counts[channels.index(name)] - a.bias if name in channels else 0
            rec[offset:offset + t["storage"] // 8] = pack(value, t)
    try:
        os.write(writer, bytes(rec))
    except (BrokenPipeError, OSError):
        os.close(writer)
        writer = None


while True:
    elapsed = time.monotonic() - start
    if a.vanish_after is not None and elapsed > a.vanish_after:
        if writer is not None:
            os.close(writer)
        shutil.rmtree(dev, ignore_errors=True)
        print("vanished", file=sys.stderr, flush=True)
        while stdin.read1(65536):  # keep the bench flowing, feed nobody
            pass
        break
    if a.eio_after is not None and elapsed > a.eio_after and not eio_done:
        raw = os.path.join(dev, "in_%s_raw" % channels[1])
        os.unlink(raw)
        os.symlink("/proc/self/mem", raw)
        eio_done = True
        print("in_%s_raw reads EIO from now on" % channels[1], file=sys.stderr, flush=True)
    r, _, _ = select.select([stdin], [], [], 0.05)
    if not r:
        continue
    chunk = stdin.read1(65536)
    if not chunk:
        break
    pending += chunk
    cut = pending.rfind(b"\n") + 1
    lines, pending = pending[:cut], pending[cut:]
    data = [f for f in (line.split() for line in lines.decode().splitlines())
            if f and not f[0].startswith("#") and len(f) >= 4]
    if not buffered:
        # A polled device shows its latest reading: the chunk's last line (writing every line's
        # three files would fall behind the bench on a slow disk).
        if data:
            counts = [float(x) for x in data[-1][1:4]]
            for i, c in enumerate(channels):
                if not (eio_done and i == 1):
                    put(os.path.join(dev, "in_%s_raw" % c), str(int(round(counts[i] - a.bias))))
        continue
    for f in data:
        t_s, counts = float(f[0]), [float(x) for x in f[1:4]]
        count += 1
        if writer is None:
            open_writer()
        if writer is None:
            continue
        if a.skip_every and count % a.skip_every == 0:
            continue
        write_record(t_s, counts)
