"""Helpers shared by the end-to-end CLI checks (tests/cli_*.py): run the real binary and expect
an exit code, and fail with a message. Each check script is run as `python3 tests/cli_X.py`, so
this module is importable from the script's own folder."""
import subprocess
import sys


def check(cond, msg):
    if not cond:
        sys.exit("FAIL: " + msg)


def runner(binary, timeout=240, stdout_limit=None):
    """Returns run(*args, expect=0, timeout=...): runs `binary args`, exits with a FAIL message
    showing stdout (cut to stdout_limit characters when given) and stderr unless the exit code is
    `expect`, and returns the CompletedProcess."""
    default_timeout = timeout

    def run(*args, expect=0, timeout=default_timeout):
        p = subprocess.run([binary, *args], capture_output=True, text=True, timeout=timeout)
        if p.returncode != expect:
            out = p.stdout if stdout_limit is None else p.stdout[:stdout_limit]
            sys.exit(f"FAIL: voronav {' '.join(args)} exited {p.returncode}, expected {expect}\n"
                     f"stdout:\n{out}\nstderr:\n{p.stderr}")
        return p

    return run
