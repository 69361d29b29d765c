"""The results table: rows land in part files as they come, a kill loses none, compaction keeps one per case."""
from __future__ import annotations

import json

import pyarrow.parquet as pq

from lab.app.sweep.cases import Case
from lab.app.sweep.sources import Source
from lab.app.sweep.table import ResultsTable, flatten, row_for, to_arrow

CASE = Case(Source("shape", "cube", "cube"), (("shading", "flat"), ("size", "64x48")))


def ok_response(mean=0.01):
    return {"status": "ok", "verdict": "pass", "failed_bars": [], "case_s": 0.2, "load_s": 0.01, "worker": "w1",
            "metrics": {"scene": "cube", "size": [64, 48], "delta_e_2000": {"mean": mean, "max": 1.5},
                        "pixels_over_1": 0.0, "coverage_mismatch": 0.0}}


def test_metrics_are_flattened_with_underscores_and_lists_kept():
    assert flatten({"a": {"b": 1, "c": {"d": 2}}, "size": [1, 2]}) == {"a_b": 1, "a_c_d": 2, "size": [1, 2]}


def test_a_row_holds_identity_settings_metrics_verdict_and_timings():
    row = row_for(CASE, ok_response(), run="r1")
    assert row["case_id"] == CASE.case_id and row["source"] == "cube" and row["kind"] == "shape"
    assert json.loads(row["settings"]) == {"shading": "flat", "size": "64x48"}
    assert row["setting_shading"] == "flat" and row["setting_size"] == "64x48"
    assert row["delta_e_2000_mean"] == 0.01 and row["size"] == [64, 48]
    assert row["verdict"] == "pass" and row["failed_bars"] is None and row["status"] == "ok"
    assert row["case_s"] == 0.2 and row["worker"] == "w1" and row["run"] == "r1"


def test_rows_with_different_columns_make_one_table():
    table = to_arrow([{"a": 1, "b": None}, {"a": 2.5, "c": "x"}])
    assert table.column_names == ["a", "b", "c"]
    assert table.to_pylist() == [{"a": 1.0, "b": None, "c": None}, {"a": 2.5, "b": None, "c": "x"}]


def test_parts_are_read_as_written_and_compaction_keeps_each_cases_latest_row(tmp_path):
    table = ResultsTable(tmp_path)
    other = Case(Source("shape", "quad", "quad"), ())
    table.append([row_for(CASE, {"status": "timeout", "error": "slow"}, "r1")], "r1")
    table.append([row_for(other, ok_response(), "r1")], "r1")
    assert table.finished() == {CASE.case_id: "timeout", other.case_id: "ok"}
    assert len(list(table.parts.glob("part-*.parquet"))) == 2, "one file per batch, written at once"

    table.compact()
    assert not table.parts.exists() and len(pq.read_table(table.path)) == 2
    again = ResultsTable(tmp_path)
    again.append([row_for(CASE, ok_response(0.02), "r2")], "r2")
    assert again.finished()[CASE.case_id] == "ok", "the later row wins"
    again.compact()
    rows = pq.read_table(again.path).to_pylist()
    assert [r["source"] for r in rows] == ["cube", "quad"]
    assert rows[0]["run"] == "r2" and rows[0]["delta_e_2000_mean"] == 0.02 and rows[1]["run"] == "r1"


def test_no_rows_write_no_part(tmp_path):
    assert ResultsTable(tmp_path).append([], "r") is None
    assert not (tmp_path / "results.parts").exists()
