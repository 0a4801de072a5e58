"""Atomic outputs: a failure half-way through writing leaves neither a partial file nor a temp."""

import pytest

from fem_racket import InputError
from fem_racket.outputs import atomic_output, provenance


def test_failure_while_writing_leaves_nothing(tmp_path):
    path = tmp_path / "out" / "result.json"
    with pytest.raises(RuntimeError), atomic_output(path) as tmp:
        tmp.write_text('{"half": ')
        raise RuntimeError("interrupted")
    assert list(tmp_path.iterdir()) == []  # not even the folder made for it


def test_failure_keeps_the_old_file_even_with_overwrite(tmp_path):
    path = tmp_path / "result.json"
    path.write_text("old")
    with pytest.raises(RuntimeError), atomic_output(path, overwrite=True) as tmp:
        tmp.write_text("new, half")
        raise RuntimeError("interrupted")
    assert path.read_text() == "old" and sorted(tmp_path.iterdir()) == [path]
    with atomic_output(path, overwrite=True) as tmp:
        assert tmp.suffix == ".json" and tmp.parent == tmp_path
        tmp.write_text("new")
    assert path.read_text() == "new" and sorted(tmp_path.iterdir()) == [path]


def test_existing_file_is_refused_without_overwrite(tmp_path):
    path = tmp_path / "result.json"
    path.write_text("old")
    with pytest.raises(InputError, match="--overwrite"), atomic_output(path):
        pass
    assert path.read_text() == "old"


def test_provenance_has_version_date_and_parameters():
    prov = provenance({"speed_m_s": 20.0, "solver": "exact"})
    assert prov["software"] == "fem_racket" and prov["version"]
    assert prov["created_utc"].endswith("+00:00")
    assert prov["parameters"] == {"speed_m_s": 20.0, "solver": "exact"}
