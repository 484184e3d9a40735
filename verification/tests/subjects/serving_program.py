#!/usr/bin/env python3
"""A serving program for the tests of the harness's program servers (program_server.h):

    serving_program.py --serve

Each request's first argument is what the run does: ok (exit status 0), status N (says
"refused this one" on stderr, status N), pid (says its process id on stderr, status 0), crash
(SIGSEGV), cwd (says its working folder on stderr, status 0), hang, lie (answers another request's id first), quiet-exit (exits 0 without
answering), chatter N (writes N bytes on stderr, status 0).
"""
import os
import signal
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "adapters", "common"))
from serve import ANSWER_FD, serve  # noqa: E402


def run(args):
    what = args[0]
    if what == "ok":
        return 0
    if what == "status":
        print("refused this one", file=sys.stderr)
        return int(args[1])
    if what == "pid":
        print(os.getpid(), file=sys.stderr)
        return 0
    if what == "cwd":
        print(os.getcwd(), file=sys.stderr)
        return 0
    if what == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    if what == "hang":
        time.sleep(3600)
    if what == "lie":
        os.write(ANSWER_FD, b"999999 0\n")
        return 0
    if what == "quiet-exit":
        os._exit(0)
    if what == "chatter":
        sys.stderr.write("x" * int(args[1]))
        return 0
    print(f"unknown request {args}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(serve(run))
