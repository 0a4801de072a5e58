"""A refinement study's CSV and sidecar hold plain numbers, read back equal to the study's.

numpy 2 writes a scalar's ``repr`` as ``np.float64(122.24625927822831)``: a CSV cell written by
``repr`` of an ``np.float64`` (a float subclass) was that text, not a number (audit A3).
"""

import csv
import math

import numpy as np
import pytest

from fem_racket.io.refine_files import write_csv
from fem_racket.studies.refine import refinement_study


@pytest.fixture(scope="module")
def study():
    return refinement_study(None, (4, 8), family="uniform", positions=(0.75,))


def _same(cell: str, value: float) -> bool:
    """``cell`` parses with float() and is ``value`` bit for bit (NaN for NaN)."""
    number = float(cell)
    return math.isnan(value) if math.isnan(number) else number == value and cell == repr(number)


def test_refine_csv_cells_are_the_study_numbers(tmp_path, study):
    path = write_csv({"uniform": study}, tmp_path / "r.csv")
    with path.open(newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["family"] for r in rows] == ["uniform", "uniform"]
    assert [int(r["elements"]) for r in rows] == [4, 8]
    orders = np.vstack([np.full((1, 4), np.nan), study.observed_order_pairs])
    for i, row in enumerate(rows):
        assert all("np." not in cell for cell in row.values()), row
        for k in range(4):
            assert _same(row[f"f{k + 1}_hz"], study.frequencies_hz[i, k])
            assert _same(row[f"f{k + 1}_exact_hz"], study.exact_frequencies_hz[k])
            assert _same(row[f"f{k + 1}_relative_error"], study.relative_error[i, k])
            assert _same(row[f"f{k + 1}_observed_order"], orders[i, k])
        assert _same(row["cor_at_0.75L"], study.cor[i, 0])
        assert _same(row["contact_time_s_at_0.75L"], study.contact_time_s[i, 0])
        assert _same(row["build_time_s"], study.build_time_s[i])
        assert _same(row["impact_time_s"], study.impact_time_s[i])
    assert rows[1]["f1_observed_order"] != "nan"  # the second row holds a computed order
