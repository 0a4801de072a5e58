"""The tension study: its script writes a table and a figure; the physics runs the right way."""

import csv

import numpy as np
from script_loader import load_script


def test_script_and_trends(tmp_path, capsys):
    files = load_script("strings_tension").main(["--out", str(tmp_path), "--quick"])
    out = capsys.readouterr().out
    assert all(str(p) in out for p in files) and len(files) == 3
    assert files[2].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with open(files[0], newline="") as fh:
        rows = list(csv.reader(fh))
    assert all(h.endswith("]") for h in rows[0])
    data = np.array(rows[1:], dtype=float)
    for pattern in ((16, 19), (18, 20)):
        sel = data[(data[:, 0] == pattern[0]) & (data[:, 1] == pattern[1])]
        assert sel.shape[0] == 3
        # higher tension: stiffer bed (k ~ T), shorter contact, lower e_A (Yang, Fafitis &
        # Wiezel 2012: tension changes dwell time and rebound)
        assert np.allclose(sel[:, 5] / sel[:, 2], sel[0, 5] / sel[0, 2], rtol=1e-12)
        assert np.all(np.diff(sel[:, 4]) < 0) and np.all(np.diff(sel[:, 3]) < 0)
    # more strings at the same tension: a stiffer bed
    assert np.all(data[data[:, 0] == 18, 5] > data[data[:, 0] == 16, 5])
