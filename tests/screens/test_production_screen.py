"""The Production screen offscreen, in the real window on the real database: reached from the
navigation, the figures and the charts of known records, the ranges by touch, read on the
worker (the screen answers at once and fills in later), the shown range exported through the
touch file chooser and read back."""

from __future__ import annotations

import csv
import io
from datetime import datetime, timedelta
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QSize
from PySide6.QtWidgets import QApplication

from app.data.csv_cells import from_csv_text
from app.data.database import Database
from app.data.production_stats import StatsRange
from app.data.records import AlarmEvent, AlarmState, PieceResult, ProductionRecord, format_utc
from app.screens.database_jobs import DatabaseJobs
from app.screens.main_window import MainWindow
from app.screens.production_screen import ProductionScreen
from app.screens.widgets.dialogs import MessageOverlay
from app.screens.widgets.file_chooser import FileChooser
from app.screens.widgets.production_charts import time_ticks
from tests.screens.helpers import find_button
from tests.screens.test_layout import cut_texts

NOW = datetime(2024, 5, 2, 10, 0).astimezone()  # local time: the 06:00-14:00 shift runs
SHIFT_START = datetime(2024, 5, 2, 6, 0).astimezone()
STEPS = {"waiting": 2.0, "centering": 0.8, "clamping": 0.6, "measuring": 0.3, "side_a": 9.0}


def record(
    at: datetime, result: PieceResult = PieceResult.OK, width_mm: float = 141.3, name: str = "B"
) -> ProductionRecord:
    return ProductionRecord(
        time=at,
        recipe_id=None,
        recipe_name=name,
        width_mm=width_mm,
        d_mm=None,
        r_mm=None,
        cycle_time_s=sum(STEPS.values()),
        result=result,
        alarm_code="E040" if result is PieceResult.ABORTED else None,
        step_times_s=STEPS,
    )


def fill(database: Database) -> None:
    at = SHIFT_START
    for minutes, width in ((10, 141.3), (20, 142.6), (50, 142.9)):  # three in 06:00-07:00
        database.record_piece(record(at + timedelta(minutes=minutes), width_mm=width))
    database.record_piece(record(at + timedelta(hours=2, minutes=5), width_mm=150.2))  # 08:xx
    database.record_piece(record(at + timedelta(hours=2, minutes=6), PieceResult.ABORTED))
    database.record_piece(record(at - timedelta(hours=1), name="=night shift"))  # 05:00
    for minutes, code in ((66, "E040"), (67, "E031"), (126, "E040")):
        database.record_alarm_event(
            AlarmEvent(
                at + timedelta(minutes=minutes),
                code,
                "text",
                "X",
                AlarmState.NORMAL,
                AlarmState.ACTIVE_UNACKED,
            )
        )


@pytest.fixture
def screen(qtbot, window: MainWindow, database: Database) -> ProductionScreen:
    fill(database)
    production = window.page("production")
    assert isinstance(production, ProductionScreen)
    production.clock = lambda: NOW
    return production


def wait_read(qtbot, screen: ProductionScreen) -> None:
    qtbot.waitUntil(lambda: not screen.loading and screen.stats is not None, timeout=10_000)


def test_the_navigation_opens_the_shift_in_figures_and_charts(
    qtbot, window: MainWindow, screen: ProductionScreen, tap
) -> None:
    tap(find_button(window, "nav_production"))
    assert window.current_key == "production"
    # The read runs on the worker: the screen answers at once and says it is reading.
    assert screen.loading and screen.status_label.text() == "Reading…"
    wait_read(qtbot, screen)
    assert screen.count_labels[PieceResult.OK].text() == "Good 4"
    assert screen.count_labels[PieceResult.ABORTED].text() == "Aborted 1"
    assert screen.count_labels[PieceResult.REJECTED].text() == "Rejected 0"
    assert screen.rate_label.text() == "1 per hour"  # 4 staves in the 4 hours since 06:00
    assert screen.alarm_count_label.text() == "Alarms 3"
    assert screen.codes_label.text() == "E040 ×2  E031 ×1"
    assert screen.range_label.text() == "02.05. 06:00 – 14:00"
    charts = screen.charts
    x, y = charts.pieces_item.getData()
    assert list(y) == [3, 0, 1, 0, 0, 0, 0, 0]  # 06:00 to 14:00, hour by hour
    assert x[0] == SHIFT_START.timestamp()
    _x, alarms = charts.alarms_item.getData()
    assert list(alarms) == [0, 2, 1, 0, 0, 0, 0, 0]
    edges, widths = charts.widths_item.getData()
    # 141.3 to 150.2 (the aborted board's 141.3 too): 1 mm bins from 141 to 151
    assert list(edges) == [float(v) for v in range(141, 152)]
    assert list(widths) == [2, 2, 0, 0, 0, 0, 0, 0, 0, 1]
    times, cycle_s = charts.cycle_item.getData()
    # Drawn without the wait for the board, as the main screen counts a cycle.
    assert len(times) == 4 and set(cycle_s) == {sum(STEPS.values()) - STEPS["waiting"]}
    _times, bound_s = charts.bound_item.getData()
    assert np.allclose(bound_s, 0.8 + 0.6 + 0.3 + 9.0)


def test_a_range_is_chosen_by_touch(
    qtbot, window: MainWindow, screen: ProductionScreen, tap
) -> None:
    window.show_screen("production")
    wait_read(qtbot, screen)
    tap(screen.range_buttons[StatsRange.TODAY])
    wait_read(qtbot, screen)
    assert screen.stats is not None and screen.stats.start == datetime(2024, 5, 2).astimezone()
    assert screen.count_labels[PieceResult.OK].text() == "Good 5"  # the night's one too
    assert screen.range_label.text() == "02.05."
    tap(screen.range_buttons[StatsRange.LAST_30_DAYS])
    wait_read(qtbot, screen)
    assert screen.choice is StatsRange.LAST_30_DAYS
    _x, y = screen.charts.pieces_item.getData()
    assert len(y) == 30 * 24 and y.sum() == 5
    tap(screen.range_buttons[StatsRange.LAST_SHIFT])  # 22:00-06:00: the one at 05:00
    wait_read(qtbot, screen)
    assert screen.count_labels[PieceResult.OK].text() == "Good 1"
    assert screen.range_label.text() == "01.05. 22:00 – 02.05. 06:00"


def test_the_shown_range_is_exported_and_reads_back(
    qtbot, window: MainWindow, screen: ProductionScreen, database: Database, tmp_path: Path
) -> None:
    window.show_screen("production")
    wait_read(qtbot, screen)
    stick = tmp_path / "stick"
    stick.mkdir()
    chooser = screen.export(stick)
    assert isinstance(chooser, FileChooser) and chooser.suffixes == (".csv",)
    assert chooser.save_name == "production-20240502-0600.csv"
    chooser.confirm()
    path = stick / "production-20240502-0600.csv"
    qtbot.waitUntil(path.exists, timeout=10_000)
    qtbot.waitUntil(
        lambda: "5 production records written" in window.top_bar.message_label.text(),
        timeout=10_000,
    )
    rows = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"), newline="")))
    stored = database.list_production(SHIFT_START, SHIFT_START + timedelta(hours=8))
    assert len(rows) == 5 and [int(r["id"]) for r in rows] == [r.id for r in stored]
    assert [r["result"] for r in rows] == ["ok", "ok", "ok", "ok", "aborted"]
    assert [from_csv_text(r["recipe_name"]) for r in rows] == ["B"] * 5


def test_an_export_that_cannot_be_written_says_why(
    qtbot, window: MainWindow, screen: ProductionScreen, tmp_path: Path
) -> None:
    window.show_screen("production")
    wait_read(qtbot, screen)
    blocked = tmp_path / "not-a-folder"
    blocked.write_text("a file where a folder should be", encoding="utf-8")
    screen.export_file(blocked / "production.csv")
    qtbot.waitUntil(lambda: window.overlay() is not None, timeout=10_000)
    overlay = window.overlay()
    assert isinstance(overlay, MessageOverlay)
    assert "not-a-folder" in overlay.message_label.text()


@pytest.mark.parametrize("language", ["en", "sl"])
def test_a_busy_month_fits_the_panel_in_both_languages(
    qtbot, window: MainWindow, database: Database, language: str
) -> None:
    """Four-digit counts, every alarm code and the longest range names: the window keeps
    1024x768 and no text is cut."""
    with database._write() as conn:  # a month of records at once (one transaction)
        conn.executemany(
            "INSERT INTO production (time, recipe_name, width_mm, cycle_time_s, result) "
            "VALUES (?, 'Barrique', ?, 25.0, ?)",
            [
                (
                    format_utc(NOW - timedelta(minutes=10 * i + 1)),
                    120.0 + i % 60,
                    ("ok", "ok", "ok", "rejected", "aborted")[i % 5],
                )
                for i in range(2500)
            ],
        )
        conn.executemany(
            "INSERT INTO alarm_events (time, code, text, source, from_state, to_state) "
            "VALUES (?, ?, 'text', 'X', 'normal', 'active_unacked')",
            [(format_utc(NOW - timedelta(hours=i)), f"E0{i % 60:02d}") for i in range(700)],
        )
    window.languages.set_language(language)
    production = window.page("production")
    assert isinstance(production, ProductionScreen)
    production.clock = lambda: NOW
    window.show_screen("production")
    production.show_range(StatsRange.LAST_30_DAYS)
    wait_read(qtbot, production)
    QApplication.processEvents()
    assert production.count_labels[PieceResult.OK].text().endswith(" 1500")
    assert production.count_labels[PieceResult.REJECTED].text().endswith(" 500")
    assert production.codes_label.text().endswith("+55")
    assert production.range_label.text() == "03.04. – 02.05."
    assert window.size() == QSize(1024, 768)
    assert cut_texts(window) == []


def test_time_ticks_are_round_hours_or_dates() -> None:
    shift = time_ticks(SHIFT_START, SHIFT_START + timedelta(hours=8))
    assert [label for _t, label in shift] == [f"{h:02d}:00" for h in range(6, 15)]
    month_start = datetime(2024, 4, 3).astimezone()
    month = time_ticks(month_start, month_start + timedelta(days=30))
    assert [label for _t, label in month] == [
        "03.04.",
        "08.04.",
        "13.04.",
        "18.04.",
        "23.04.",
        "28.04.",
        "03.05.",
    ]


def test_only_the_newest_request_of_a_kind_is_answered(qtbot, database: Database) -> None:
    """Tapping ranges quickly: the figures of the last tap are shown, never an older answer
    that arrives later."""
    jobs = DatabaseJobs(database.path)
    answers: list[object] = []
    for hours in (1, 2, 3):
        jobs.run(
            "stats",
            lambda db, h=hours: (h, len(db.list_production(NOW - timedelta(hours=h), NOW))),
            lambda result, error: answers.append(result or error),
        )
    jobs.run("other", lambda db: "other", lambda result, error: answers.append(result))
    jobs.wait()
    qtbot.waitUntil(lambda: len(answers) == 2, timeout=10_000)
    assert answers == [(3, 0), "other"]
    jobs.run("stats", lambda db: db.no_such_method(), lambda r, e: answers.append(e))
    jobs.wait()
    qtbot.waitUntil(lambda: len(answers) == 3, timeout=10_000)
    assert "AttributeError" in str(answers[-1])
