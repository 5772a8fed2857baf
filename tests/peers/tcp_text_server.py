# The virtual bench over TCP text, as a board piping its ADC would serve it: sample lines read
# from stdin (`accelcal record --source sim -o -`) go to the connected client, a line at a time;
# lines that come while nobody is connected are dropped (a live sensor does not wait). Prints its
# port first. A new client replaces the old one (a wizard started again after a kill).
# Usage: accelcal record --source sim ... -o - | python3 tcp_text_server.py
import select, socket, sys

server = socket.socket()
server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
server.bind(("127.0.0.1", 0))
server.listen(4)
print("port %d" % server.getsockname()[1], flush=True)
client = None
stdin = sys.stdin.buffer
pending = b""
while True:
    ready, _, _ = select.select([server, stdin], [], [], 1.0)
    if server in ready:
        c, _ = server.accept()
        if client is not None:
            client.close()
        client = c
    if stdin in ready:
        chunk = stdin.read1(65536)
        if not chunk:
            break
        pending += chunk
        cut = pending.rfind(b"\n") + 1
        lines, pending = pending[:cut], pending[cut:]
        if client is not None and lines:
            try:
                client.sendall(lines)
            except OSError:
                client.close()
                client = None
