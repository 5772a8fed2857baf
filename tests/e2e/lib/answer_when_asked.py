# Runs a command and answers its questions as a technician at a live bench would: each answer
# only once its question is on the screen, with pauses and bench actions between (issue 27,
# item 6: a pose changed while a question waits).
# Usage: python3 answer_when_asked.py SCRIPT OUTPUT -- COMMAND...
# SCRIPT: one action per line:
#   ask TEXT       wait until TEXT appears in the output after the previous `ask` (60 s at most)
#   enter_until TEXT  Enter at every question (the output stopped at its "> ") until TEXT appears
#                  (120 s at most); TEXT's question is left for the next action
#   send TEXT      type TEXT and Enter ("send" alone: Enter)
#   sleep S        wait S seconds
#   write FILE T   write T into FILE (the bench's control: turn the sensor)
# The command's output (stdout and stderr) goes to OUTPUT. Exits with the command's status, or
# 3 when a question never came (the output then ends with what was seen).
import subprocess, sys, threading, time

script_path, output_path = sys.argv[1], sys.argv[2]
command = sys.argv[sys.argv.index("--") + 1:]
out = open(output_path, "wb")
proc = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
seen = bytearray()
lock = threading.Lock()


def pump():
    while True:
        chunk = proc.stdout.read1(4096)
        if not chunk:
            return
        with lock:
            seen.extend(chunk)
        out.write(chunk)
        out.flush()


reader = threading.Thread(target=pump, daemon=True)
reader.start()
cursor = 0
for line in open(script_path):
    line = line.rstrip("\n")
    if not line.strip():
        continue
    verb, _, rest = line.partition(" ")
    if verb == "ask":
        deadline = time.monotonic() + 60
        while True:
            with lock:
                at = seen.find(rest.encode(), cursor)
            if at >= 0:
                cursor = at + len(rest)
                break
            if time.monotonic() > deadline or (proc.poll() is not None and not reader.is_alive()):
                out.write(("\n[answer_when_asked: never asked: %s]\n" % rest).encode())
                proc.kill()
                sys.exit(3)
            time.sleep(0.05)
    elif verb == "enter_until":
        deadline = time.monotonic() + 120
        last_size = -1
        while True:
            with lock:
                tail = bytes(seen[cursor:])
                size = len(seen)
            at = tail.find(rest.encode())
            if at >= 0:
                cursor += at + len(rest)
                break
            # A question waits: the output ends with its "> " and has stopped growing.
            if tail.endswith(b"> ") and size == last_size:
                cursor = size
                proc.stdin.write(b"\n")
                proc.stdin.flush()
            last_size = size
            if time.monotonic() > deadline or (proc.poll() is not None and not reader.is_alive()):
                out.write(("\n[answer_when_asked: never asked: %s]\n" % rest).encode())
                proc.kill()
                sys.exit(3)
            time.sleep(0.03)
    elif verb == "send":
        proc.stdin.write((rest + "\n").encode())
        proc.stdin.flush()
    elif verb == "sleep":
        time.sleep(float(rest))
    elif verb == "write":
        path, _, text = rest.partition(" ")
        with open(path, "w") as f:
            f.write(text)
    else:
        sys.exit("answer_when_asked: unknown action: " + line)
proc.stdin.close()
status = proc.wait(timeout=120)
reader.join(5)
sys.exit(status)
