"""Warnings in a run file's attributes: one a line, in the order they arose."""

from __future__ import annotations

from pipeline.results.notes import joined, lines, run_notes


def test_texts_holding_semicolons_come_back_whole():
    texts = ("preload not used; set preload_kgf", "fracture at 443 kN")
    assert lines(joined(texts)) == texts
    assert lines("") == () and joined([]) == ""


def test_run_notes_are_the_readers_then_the_stages_then_the_extractions():
    attrs = {"messages": "speed 3 % off", "warnings": "channel cut\nfracture",
             "ingest_warnings": "line 7 truncated", "title": "not a warning"}
    assert run_notes(attrs) == ["line 7 truncated", "channel cut", "fracture", "speed 3 % off"]
    assert run_notes({}) == []
