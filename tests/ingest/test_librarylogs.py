"""A library's log records, collected while a file is read instead of printed."""

import logging
import threading

import pytest

from pipeline.ingest.librarylogs import collected_logs

PREFIX = "chainbench_test_library"


@pytest.fixture
def library():
    """Two module loggers of a library, each with its own handler (as npTDMS sets them up)."""
    loggers = [logging.getLogger(f"{PREFIX}.{module}") for module in ("reader", "segment")]
    handler = logging.Handler()
    records = []
    handler.emit = records.append
    for logger in loggers:
        logger.addHandler(handler)
        logger.setLevel(logging.INFO)
    yield loggers, records
    for logger in loggers:
        logger.removeHandler(handler)
        logger.setLevel(logging.NOTSET)


def test_warnings_of_this_thread_are_collected_once(library, caplog):
    (reader, segment), printed = library
    with collected_logs(PREFIX) as logged:
        reader.warning("segment %d incomplete", 3)
        segment.warning("data size 5 is odd")
        reader.warning("segment %d incomplete", 3)
        reader.info("below warning")
    assert logged == ["segment 3 incomplete", "data size 5 is odd"]
    assert [record.getMessage() for record in printed] == ["below warning"]
    assert [record.getMessage() for record in caplog.records] == ["below warning"]


def test_other_threads_log_as_before(library):
    (reader, _), printed = library
    with collected_logs(PREFIX) as logged:
        other = threading.Thread(target=reader.warning, args=("from another thread",))
        other.start()
        other.join()
    assert logged == []
    assert [record.getMessage() for record in printed] == ["from another thread"]


def test_loggers_are_restored_after_an_error(library):
    (reader, segment), printed = library
    with pytest.raises(ValueError), collected_logs(PREFIX):
        raise ValueError
    assert reader.filters == segment.filters == []
    reader.warning("after")
    assert [record.getMessage() for record in printed] == ["after"]
