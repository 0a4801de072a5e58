"""The command line run in-process, as the CLI tests drive it."""

import json

from fem_racket.cli import main


def run(capsys, *argv):
    """``fem-racket ARGV`` (each argument as a string): exit code, stdout, stderr."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def run_json(capsys, *argv):
    """``fem-racket ARGV --json``, which must exit 0 (else its stderr is shown): the printed
    JSON."""
    code, out, err = run(capsys, *argv, "--json")
    assert code == 0, err
    return json.loads(out)
