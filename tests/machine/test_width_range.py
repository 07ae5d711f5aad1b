"""The widths each recipe cuts on this machine: the alarm for a board outside them names both
numbers before anything moves, and the shipped samples fit the shipped simulation."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.config import load_config
from app.drivers.sim.settings import parse_gauge_settings, parse_sim_settings
from app.geometry.width_range import cuttable_widths
from app.machine import commands as cmd
from app.machine.process_params import stave_limits
from app.machine.states import MachineState
from tests.machine.conftest import make_rig


def test_the_barrique_range_is_bounded_by_the_tilt_axis(tmp_path: Path) -> None:
    rig = make_rig(tmp_path)
    try:
        c = rig.controller
        recipe = c.store.recipe_by_name("Barrique 225 l Bordeaux")
        assert recipe is not None
        widths = cuttable_widths(recipe.stave, c.store.parameters(), stave_limits(c.config))
        assert widths is not None
        assert 170.0 < widths.max_mm < 190.0 and widths.min_mm < 100.0
        assert widths.refusal(199.9).startswith("board 199.9 mm: this recipe cuts boards at most")
        assert widths.refusal(150.0) == ""
    finally:
        rig.runtime.shutdown()


def test_a_board_too_wide_raises_one_alarm_with_both_widths_before_anything_moves(
    tmp_path: Path,
) -> None:
    rig = make_rig(tmp_path)
    try:
        rig.home()
        rig.select()
        rig.load(199.9)
        still = rig.positions()
        rig.send(cmd.Start())
        rig.until(lambda c: c.state is MachineState.ERROR, 30.0)
        alarms = [a for a in rig.controller.alarms.views() if a.code == "E032"]
        assert len(alarms) == 1
        text = alarms[0].text
        assert "199.9 mm" in text and "at most 178" in text and "take the board off" in text
        assert rig.positions() == pytest.approx(still, abs=0.01), "nothing moved"
        assert rig.controller.partly_cut.board is None
    finally:
        rig.runtime.shutdown()


def test_the_shipped_samples_cut_every_board_the_shipped_simulation_puts_in(
    tmp_path: Path,
) -> None:
    config = load_config()
    sim = parse_sim_settings(config.backend_settings.get("sim", {}), config.axes)
    gauge = parse_gauge_settings(config.gauge_settings.get("sim", {}))
    rig = make_rig(tmp_path)
    try:
        store = rig.controller.store
        params, limits = store.parameters(), stave_limits(config)
        for recipe in store.recipes():
            widths = cuttable_widths(recipe.stave, params, limits)
            assert widths is not None, recipe.name
            for distribution in (sim.board_widths, gauge.widths):
                assert widths.contains(distribution.min_mm), recipe.name
                assert widths.contains(distribution.max_mm), recipe.name
    finally:
        rig.runtime.shutdown()
