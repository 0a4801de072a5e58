"""The command line run in-process, as the CLI tests drive it."""

from fem_racket.cli import main


def run(capsys, *argv):
    """``fem-racket ARGV`` (each argument as a string): exit code, stdout, stderr."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err
