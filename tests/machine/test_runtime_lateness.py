"""The real-time loop's lateness samples: bounded, and the figures come from the newest."""

from __future__ import annotations

import pytest

from app.machine.runtime import LatenessStats


def test_samples_never_exceed_the_limit_and_the_oldest_go_first() -> None:
    stats = LatenessStats(limit=100)
    for k in range(1000):
        stats.add(k / 1000.0)
        assert len(stats.samples) <= 100
    assert stats.samples[-1] == pytest.approx(0.999)
    assert min(stats.samples) >= 0.9  # everything older than the last 100 was dropped
    summary = stats.summary()
    assert summary["max_ms"] == pytest.approx(999.0)
    assert summary["p50_ms"] >= 900.0
