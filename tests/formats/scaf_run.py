"""tests/formats/scaf_run: running the `scaf` program from the format tests.

The program is argv[1] (or $SCAF_BINARY); every test works in its own
temporary folder under $SCAF_TEST_TMPDIR (the build's test-tmp) and removes
it when it passes.
"""
import os
import subprocess
import sys
import tempfile

SCAF = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("SCAF_BINARY", "scaf")


def run(args, stdin=None, cwd=None):
    """Run scaf with args (a list); returns (exit status, stdout bytes, stderr text)."""
    p = subprocess.run([SCAF] + args, input=stdin, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, cwd=cwd, timeout=600)
    return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")


def workdir(name):
    base = os.environ.get("SCAF_TEST_TMPDIR") or None
    if base:
        os.makedirs(base, exist_ok=True)
    return tempfile.TemporaryDirectory(prefix=name + "-", dir=base)


def expect(cond, what):
    if not cond:
        raise AssertionError(what)
