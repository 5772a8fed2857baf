#!/usr/bin/env python3
"""Runs the wizard in line mode and answers its questions one at a time, as a technician would:
a line is written only when the wizard waits for one (its output ends with "> " and stays quiet),
never ahead of time as a pipe from `yes` does. So a question can be answered by what it asks.

Usage: answer_prompts.py [--first ANSWER]... [--when TEXT=ANSWER]... [--timeout S] -- COMMAND...
  --first ANSWER     the first questions' answers, in order
  --when TEXT=ANSWER after those: a question whose text since the previous answer contains TEXT
                     gets ANSWER (the first such rule that matches); every other question gets ""
The wizard's output is copied to standard output, each answer after its prompt; the exit status
is the wizard's (124 when it outlived --timeout).
"""
import argparse
import os
import select
import subprocess
import sys
import time


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--first", action="append", default=[])
    parser.add_argument("--when", action="append", default=[])
    parser.add_argument("--timeout", type=float, default=900.0)
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    rules = [rule.split("=", 1) for rule in args.when]
    firsts = list(args.first)

    wizard = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    out = wizard.stdout.fileno()
    since_answer = b""
    deadline = time.monotonic() + args.timeout
    quiet_s = 0.3  # a prompt followed by this much silence is a question waiting
    while True:
        if time.monotonic() > deadline:
            wizard.kill()
            wizard.wait()
            return 124
        ready, _, _ = select.select([out], [], [], quiet_s)
        if ready:
            chunk = os.read(out, 65536)
            if not chunk:
                break
            sys.stdout.buffer.write(chunk)
            sys.stdout.flush()
            since_answer += chunk
            continue
        if not since_answer.endswith(b"> "):
            continue
        text = since_answer.decode("utf-8", "replace")
        if firsts:
            answer = firsts.pop(0)
        else:
            answer = next((a for t, a in rules if t in text), "")
        sys.stdout.write(answer + "\n")
        sys.stdout.flush()
        since_answer = b""
        try:
            wizard.stdin.write((answer + "\n").encode())
            wizard.stdin.flush()
        except BrokenPipeError:
            break
    return wizard.wait()


if __name__ == "__main__":
    sys.exit(main())
