"""The serving side of crossdiv's program protocol, for a Python program.

A program that is slow to start (an interpreter importing Open3D, Blender) serves instead of
being started for every run: the harness (verification's program_server.h) starts it once and
sends each run's arguments on its standard input, one JSON line each,

    {"id": 7, "args": ["loop", "2", "/tmp/.../in.off", "/tmp/.../out.ply"]}

and reads the answer on file descriptor 3, one line per request: the id and the exit status the
run would have had when started alone, "7 0". What a run says goes to stderr as usual. The end
of standard input ends the program.

    from serve import serve
    serve(lambda args: main([sys.argv[0]] + args))
"""
import json
import os
import sys
import traceback

# The descriptor the answers go to (program_server.h).
ANSWER_FD = 3


def exit_status(code):
    """The status sys.exit(code) would give a process."""
    if code is None:
        return 0
    if isinstance(code, int):
        return code & 0xFF
    print(code, file=sys.stderr)
    return 1


def serve(run):
    """Answers every request on standard input with run(args) -> exit status, until its end.

    An exception a run raises is that run's failure (its traceback on stderr, status 1), as it
    would have been for a program started per run; SystemExit gives its status. The next request
    is served as if nothing happened: every run writes a file of its own.
    """
    try:
        answers = os.fdopen(ANSWER_FD, "w", buffering=1)
    except OSError as e:
        print(f"serve: no descriptor {ANSWER_FD} to answer on ({e}); this program serves crossdiv's harness only",
              file=sys.stderr)
        return 2
    for line in sys.stdin:
        try:
            request = json.loads(line)
            number, args = int(request["id"]), [str(a) for a in request["args"]]
        except (ValueError, KeyError, TypeError) as e:
            print(f"serve: not a request: {line.strip()[:200]!r} ({e})", file=sys.stderr)
            return 2
        try:
            status = exit_status(run(args))
        except SystemExit as e:
            status = exit_status(e.code)
        except Exception:  # the run's failure, not the server's
            traceback.print_exc()
            status = 1
        sys.stdout.flush()
        sys.stderr.flush()
        answers.write(f"{number} {status}\n")
    return 0
