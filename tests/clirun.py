"""The command line run in-process, as the CLI tests drive it."""

import json
import re
from pathlib import Path

import pytest

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError


def run(capsys, *argv):
    """``fem-racket ARGV`` (each argument as a string): exit code, stdout, stderr."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def run_ok(capsys, *argv):
    """``fem-racket ARGV``, which must exit 0 (else its stderr is shown): its stdout."""
    code, out, err = run(capsys, *argv)
    assert code == 0, err
    return out


def run_json(capsys, *argv):
    """``fem-racket ARGV --json``, which must exit 0 (else its stderr is shown): the printed
    JSON."""
    return json.loads(run_ok(capsys, *argv, "--json"))


def refused_alike(capsys, argv, method, words, *, start=False):
    """``fem-racket ARGV`` and the run file's Python ``method()`` refuse alike: the command exits
    2 with one line holding ``words``, the method raises InputError holding them (beginning with
    them when ``start``)."""
    line = one_error(capsys, *argv)
    assert words in line, line
    with pytest.raises(InputError, match=("^" if start else "") + re.escape(words)):
        method()


def file_refused_alike(capsys, text, argv, method, words, *, start=False):
    """A run file ``run.toml`` holding ``text``, written in the working folder, is refused alike
    (:func:`refused_alike`) by ``fem-racket ARGV`` (which names ``--config run.toml``) and by
    ``method(load_config("run.toml"))``; neither writes a file (the run file is all the folder
    holds)."""
    Path("run.toml").write_text(text)
    refused_alike(capsys, argv, lambda: method(load_config("run.toml")), words, start=start)
    assert sorted(p.name for p in Path().iterdir()) == ["run.toml"]


def one_error(capsys, *argv):
    """``fem-racket ARGV``, which must be refused as every bad input is: exit 2, one line on
    stderr (``fem-racket ...: error: ...``), no traceback. The line."""
    code, out, err = run(capsys, *argv)
    assert code == 2, (out, err)
    assert "Traceback" not in err
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("fem-racket") and ": error: " in lines[0]
    return lines[0]


def library_error(call):
    """``call()``, which must be refused as the library refuses bad input: an InputError of one
    line. The line (the library's counterpart of :func:`one_error`)."""
    with pytest.raises(InputError) as err:
        call()
    text = str(err.value)
    assert "\n" not in text
    return text


def refused_before_any_file(capsys, *argv):
    """:func:`one_error` for ``fem-racket ARGV`` run in an empty working folder (the ``cwd``
    fixture), which must stay empty: refused before anything is written. The line."""
    line = one_error(capsys, *argv)
    assert not any(Path().iterdir()), "a file was written"
    return line
