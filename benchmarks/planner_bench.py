"""Figures of the trajectory planner and the path executor (issue "near-optimal, exact, and
on time", point 3). Prints one table per figure; nothing here is asserted.

    .venv/bin/python benchmarks/planner_bench.py              # everything (about 3 min)
    .venv/bin/python benchmarks/planner_bench.py --lateness-s 0   # skip the lateness part

For reference staves (lengths 900, 2000, 3500 mm; several widths, ratios and tilts), with the
default machine configuration (feed 120 mm/s; X 400 mm/s, 2000 mm/s^2, 20000 mm/s^3; Y 300,
2000, 20000; Z 30 deg/s, 150, 1500) and the default process parameters:

* cut ratio: planned time of each side (lead-in start to lead-out end, at rest at both ends)
  divided by the lower bound length/feed + feed/accel, where accel is the largest tangential
  acceleration the axis limits allow anywhere on that side (no jerk limit: a true lower
  bound; target <= 1.02). "jerk bound" is the same with the unavoidable jerk-limited ramps
  (length/feed + the time an S-curve ramp to the feed loses): ours is time-optimal if ~1.000.
* motion time of the whole stave and an estimated cycle time (motion + the configured
  centring, clamping, spindle run-up and unclamping times) against the 90 s requirement.
* the executor's setpoint stream at 4 ms, finite-differenced: largest |v|, |a|, |j| of any
  axis over its limit (targets 1.001, 1.01, <= 1 except at the declared curvature steps;
  the jerk at those steps is shown separately).
* largest distance from the exact tool path of the setpoints and of the chords between
  them while cutting (target 0.001 mm), and of the actual positions of the simulated drives
  (app.drivers.sim: CiA 402 drives, PI position loop, friction) fed with that stream
  (target 0.01 mm), on the board (P1..P4, P5..P8) and over the whole cut (leads included).
* per side-profile family (line-arc-line, single arc, parabola, ellipse arc, superellipse,
  the shipped drawn profile) on one stave: the same cut ratios, the number of lines and arcs
  cut per side, and the largest jerk ratio between the arcs of a fitted curve (the planner
  keeps it <= 1; only where a line meets an arc is the jerk a declared step).
* planning time of a whole stave (target 200 ms): plan_stave alone, median of 10.
* executor lateness p50/p99/max over --lateness-s seconds at 4 ms, the machine process
  alone and with the operator application plotting live (see :func:`measure_lateness`).
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from app.config import MachineConfig, parse_config  # noqa: E402
from app.geometry.curved_profile import ProfileSpec  # noqa: E402
from app.geometry.profile import solve_profile  # noqa: E402
from app.geometry.profile_kinds import ProfileKind  # noqa: E402
from app.geometry.toolpath import ToolPath, ToolPathParams, build_toolpath  # noqa: E402
from app.machine.cycle_floor import jerk_limited_cut_s  # noqa: E402
from app.machine.executor import ExecutorOutput, PathExecutor  # noqa: E402
from app.machine.planner.chunk import path_box  # noqa: E402
from app.machine.planner.keepout import TableKeepOut  # noqa: E402
from app.machine.planner.limits import MotionLimits  # noqa: E402
from app.machine.planner.stave_plan import StavePlan, plan_stave  # noqa: E402

PERIOD_S = 0.004
CYCLE_REQUIREMENT_S = 90.0


@dataclass(frozen=True)
class Stave:
    length_mm: float
    width_mm: float
    length_ratio: float
    width_ratio: float
    tilt_deg: float

    @property
    def label(self) -> str:
        return (
            f"{self.length_mm:4.0f}x{self.width_mm:3.0f} l={self.length_ratio:.3f} "
            f"k={self.width_ratio:.3f} a={self.tilt_deg:g}"
        )


REFERENCE_STAVES = (
    Stave(900.0, 100.0, 0.25, 0.75, 10.0),
    Stave(900.0, 280.0, 0.45, 60.0 / 280.0, 20.0),
    Stave(2000.0, 150.0, 1.0 / 3.0, 2.0 / 3.0, 10.0),
    Stave(2000.0, 250.0, 0.0, 0.5, 15.0),
    Stave(3500.0, 200.0, 0.25, 0.75, 5.0),
    Stave(3500.0, 280.0, 0.2, 0.3, 10.0),
)


def _params(stave: Stave, config: MachineConfig) -> ToolPathParams:
    p = config.process
    return ToolPathParams(
        tool_radius_mm=p.tool_radius_mm,
        machine_height_mm=p.machine_height_mm,
        tilt_deg=stave.tilt_deg,
        start_x_mm=p.start_x_mm,
        start_y_mm=p.start_y_mm,
        lead_mm=p.lead_mm,
        home_x_mm=config.axes["X"].home_position,
        home_y_mm=config.axes["Y"].home_position,
        home_z_deg=config.axes["Z"].home_position,
        tilt_clearance_mm=p.tilt_clearance_mm,
    )


FAMILY_STAVE = Stave(1000.0, 150.0, 0.25, 0.75, 10.0)
FAMILIES: tuple[tuple[str, ProfileSpec], ...] = (
    ("line-arc-line 1/4", ProfileSpec()),
    ("single arc", ProfileSpec(ProfileKind.SINGLE_ARC)),
    ("parabola", ProfileSpec(ProfileKind.PARABOLA)),
    ("ellipse arc s=1.2", ProfileSpec(ProfileKind.ELLIPSE, (("semi_axis_ratio", 1.2),))),
    (
        "superellipse n=4 s=1.2",
        ProfileSpec(ProfileKind.SUPERELLIPSE, (("exponent", 4.0), ("semi_axis_ratio", 1.2))),
    ),
    (
        "superellipse n=10 s=1.05",
        ProfileSpec(ProfileKind.SUPERELLIPSE, (("exponent", 10.0), ("semi_axis_ratio", 1.05))),
    ),
)


def family_rows(config: MachineConfig, limits: MotionLimits) -> list[dict[str, Any]]:
    """The cut ratios of every profile family on FAMILY_STAVE (planning only)."""
    from app.data.dxf_profile import read_dxf_profile

    sample = ROOT / "resources" / "profiles" / "sample_side_profile.dxf"
    drawn = read_dxf_profile(sample.name, sample.read_bytes()).shape
    families = (*FAMILIES, ("drawn (sample DXF)", ProfileSpec(ProfileKind.DRAWN, drawn=drawn)))
    s = FAMILY_STAVE
    rows = []
    for name, spec in families:
        profile = spec.solve(s.length_mm, s.width_mm, s.width_ratio, s.length_ratio)
        toolpath = build_toolpath(profile, _params(s, config))
        start = (toolpath.params.home_x_mm, toolpath.params.home_y_mm, toolpath.params.home_z_deg)
        plan = plan_stave(toolpath, start, limits)
        xyz = plan.setpoints(PERIOD_S)[:, 1:]
        _, _, jerk, _, _ = stream_ratios(plan, xyz, limits)
        rows.append(
            {
                "family": name,
                "pieces": len(profile.edge("A")),
                "ratio_a": cut_ratios(plan, limits, "A"),
                "ratio_b": cut_ratios(plan, limits, "B"),
                "jerk": jerk,
            }
        )
    return rows


def print_family_table(rows: list[dict[str, Any]]) -> None:
    s = FAMILY_STAVE
    print(
        f"\nCut time per side-profile family ({s.length_mm:.0f} x {s.width_mm:.0f} mm, "
        f"k = {s.width_ratio:g}, tilt {s.tilt_deg:g} deg), against length/feed + feed/accel"
    )
    print(f"{'family':28} {'pieces':>6} {'A/bound':>8} {'B/bound':>8} {'A/jerk':>7} {'j/limit':>8}")
    for r in rows:
        print(
            f"{r['family']:28} {r['pieces']:6d} {r['ratio_a'][0]:8.4f} {r['ratio_b'][0]:8.4f} "
            f"{r['ratio_a'][1]:7.4f} {r['jerk']:8.3f}"
        )


def toolpath_for(stave: Stave, config: MachineConfig) -> ToolPath:
    profile = solve_profile(stave.length_mm, stave.width_mm, stave.length_ratio, stave.width_ratio)
    return build_toolpath(profile, _params(stave, config))


# -- figures of one stave -------------------------------------------------------------------


def run_executor(plan: StavePlan) -> list[ExecutorOutput]:
    executor = PathExecutor(plan, PERIOD_S)
    outputs = [executor.last_output]
    while not executor.done:
        outputs.append(executor.step())
    return outputs


def cut_ratios(plan: StavePlan, limits: MotionLimits, side: str) -> tuple[float, float]:
    """(planned / (L/f + f/a), planned / jerk-limited bound) for one side."""
    path = plan.cut_path(side)
    feed = limits.feed_mm_s
    accel = max(
        path_box(piece.bounds(), limits.x, limits.y, math.inf, math.inf).acceleration
        for piece in path.pieces
    )
    planned = plan.cut_time_s(side)
    bound = path.length_mm / feed + feed / accel
    return planned / bound, planned / jerk_limited_cut_s(path, limits)


def chord_distances(plan: StavePlan, xy: np.ndarray) -> np.ndarray:
    """Largest distance from the path of 9 interior points of each chord between setpoints."""
    if len(xy) < 2:
        return np.zeros(0)
    fractions = np.linspace(0.1, 0.9, 9)
    a, b = xy[:-1], xy[1:]
    points = a[:, None, :] + (b - a)[:, None, :] * fractions[None, :, None]
    flat = points.reshape(-1, 2)
    return plan.distances_to_path(flat[:, 0], flat[:, 1]).reshape(len(a), -1).max(axis=1)


def stream_ratios(
    plan: StavePlan, xyz: np.ndarray, limits: MotionLimits
) -> tuple[float, float, float, float, str]:
    """(v, a, j outside steps, j at steps) as largest ratio to the limit over the axes."""
    v = np.diff(xyz, axis=0) / PERIOD_S
    a = np.diff(v, axis=0) / PERIOD_S
    j = np.diff(a, axis=0) / PERIOD_S
    lim = np.array([[ax.velocity, ax.acceleration, ax.jerk] for ax in limits.axes])
    mask = np.ones(len(j), dtype=bool)
    for t in plan.curvature_step_times():
        k = int(t / PERIOD_S)
        mask[max(k - 3, 0) : k + 2] = False
    vr = np.abs(v).max(axis=0) / lim[:, 0]
    ar = np.abs(a).max(axis=0) / lim[:, 1]
    jr = np.abs(j[mask]).max(axis=0) / lim[:, 2]
    js = np.abs(j[~mask]).max(axis=0) / lim[:, 2] if np.any(~mask) else np.zeros(3)
    axis = "XYZ"[int(np.argmax(jr))]
    return float(vr.max()), float(ar.max()), float(jr.max()), float(js.max()), axis


def simulated_path_error(
    plan: StavePlan, outputs: list[ExecutorOutput], config: MachineConfig
) -> tuple[float, float]:
    """Feed the stream to the simulated drives; (on the board, whole cut) largest distance
    of the actual X-Y from the exact path, in mm."""
    from app.drivers.registry import create_backend

    backend = create_backend(config.with_backend("sim"))
    motion = backend.motion
    if motion.lifecycle_state.name == "UNCONFIGURED":
        motion.configure()
    motion.activate()
    for axis in ("X", "Y", "Z"):
        motion.enable(axis)
    for _ in range(25):
        motion.advance(PERIOD_S)  # type: ignore[attr-defined]
    if not all(fb.enabled for fb in motion.read_axes().values()):
        raise RuntimeError("the simulated drives did not enable")
    actual = []
    for out in outputs:
        motion.write_setpoints({"X": out.x, "Y": out.y, "Z": out.z})
        motion.advance(PERIOD_S)  # type: ignore[attr-defined]
        fb = motion.read_axes()
        actual.append((fb["X"].position, fb["Y"].position))
    motion.deactivate()
    motion.shutdown()
    xy = np.array(actual)
    # The actual position read after the period belongs to the setpoint of that period.
    cutting = np.array([o.cutting for o in outputs])
    whole = float(plan.distances_to_path(xy[cutting, 0], xy[cutting, 1]).max())
    board = []
    for side in ("A", "B"):
        on_board = side_board_mask(plan, side, np.array([(o.x, o.y) for o in outputs]))
        board.append(float(plan.distances_to_path(xy[on_board, 0], xy[on_board, 1]).max()))
    return max(board), whole


def side_board_mask(plan: StavePlan, side: str, setpoints_xy: np.ndarray) -> np.ndarray:
    """Setpoints on the board part of a side (P1..P4 or P5..P8, leads excluded)."""
    board = plan.board_path(side)
    return board.distances(setpoints_xy[:, 0], setpoints_xy[:, 1]) < 1e-6


def keep_out_cost_s(toolpath: ToolPath, start: tuple[float, float, float]) -> float:
    """What the keep-out model costs one cycle's plan: routing the approach from where the
    axes stand (home: the tool path's first point, so no detour) to the tool path's start."""
    first = toolpath.segments[0]
    target = (*first.start, first.z_start_deg)
    runs = 1000
    t0 = time.perf_counter()
    for _ in range(runs):
        TableKeepOut.around_toolpath(toolpath).route(start, target)
    return (time.perf_counter() - t0) / runs


def stave_figures(
    stave: Stave, config: MachineConfig, limits: MotionLimits, *, simulate: bool
) -> dict[str, Any]:
    toolpath = toolpath_for(stave, config)
    start = (
        config.axes["X"].home_position,
        config.axes["Y"].home_position,
        config.axes["Z"].home_position,
    )
    timings = []
    for _ in range(10):
        t0 = time.perf_counter()
        plan = plan_stave(toolpath, start, limits)
        timings.append(time.perf_counter() - t0)
    keep_out_s = keep_out_cost_s(toolpath, start)
    outputs = run_executor(plan)
    xyz = np.array([(o.x, o.y, o.z) for o in outputs])
    cutting = np.array([o.cutting for o in outputs])
    v, a, j, j_steps, j_axis = stream_ratios(plan, xyz, limits)
    setpoint_error = float(plan.distances_to_path(xyz[cutting, 0], xyz[cutting, 1]).max())
    chord = chord_distances(plan, xyz[:, :2])
    chord_cut = cutting[1:] & cutting[:-1]
    io = config.io
    overhead_s = io.centering_time_s + io.clamp_time_s + io.spindle_runup_s + io.clamp_time_s
    figures: dict[str, Any] = {
        "stave": stave.label,
        "ratio_a": cut_ratios(plan, limits, "A"),
        "ratio_b": cut_ratios(plan, limits, "B"),
        "motion_s": plan.duration_s,
        "cycle_s": plan.duration_s + overhead_s,
        "v": v,
        "a": a,
        "j": j,
        "j_steps": j_steps,
        "j_axis": j_axis,
        "setpoint_mm": setpoint_error,
        "chord_mm": float(chord[chord_cut].max()),
        "plan_ms": statistics.median(timings) * 1e3,
        "plan_max_ms": max(timings) * 1e3,
        "keep_out_us": keep_out_s * 1e6,
        "sim": None,
    }
    if simulate:
        figures["sim"] = simulated_path_error(plan, outputs, config)
    return figures


# -- lateness --------------------------------------------------------------------------------


def lateness_config() -> MachineConfig:
    """The simulation with a simulated operator feeding boards of about 110 mm (sample
    recipe 1 derives its tilt from the width; wider boards need more than the Z travel),
    and soft limits 20 mm/deg below the home switches: after homing the simulated axes
    stand a few hundredths beyond the switch edge, i.e. outside the default soft limits,
    and the cycle's soft-limit check would refuse the first setpoint."""
    return parse_config(
        {
            "backend": {
                "name": "sim",
                "sim": {
                    "auto_load": True,
                    "operator_delay_s": 0.5,
                    "board_width_mean_mm": 110.0,
                    "board_width_sd_mm": 5.0,
                },
            },
            "axes": {
                "X": {"min_position": -20.0, "home_switch_position": -5.0},
                "Y": {"min_position": -20.0, "home_switch_position": -5.0},
                "Z": {"min_position": -20.0, "home_switch_position": -15.0},
            },
        }
    )


@dataclass
class _CycleTally:
    last: Any
    cycles: int = 0
    alarms: int = 0
    started_s: float = 0.0


def measure_lateness(
    duration_s: float = 60.0,
    *,
    with_gui: bool = False,
    realtime_priority: bool = True,
    config: MachineConfig | None = None,
    db_path: Path | None = None,
) -> dict[str, Any]:
    """Run the machine process (``app.machine.process_link``) on the simulation, home it,
    then let it cut staves back to back for ``duration_s`` of wall time (simulated operator
    feeding boards, sample recipe 1), and return its loop lateness {"periods", "p50_ms",
    "p99_ms", "max_ms", "overruns"} (whole process life) plus "cycles" (cycles that ended
    in READY), "alarms" (cycles that ended otherwise) and "gui" (what ran in this process
    meanwhile). ``realtime_priority`` asks for SCHED_FIFO (granted only with the privilege).

    With ``with_gui`` this process runs the operator application's main window on the same
    link (offscreen if there is no display) and, beside it, a live plot of the three axis
    positions (3 curves x 7,500 points redrawn at 30 fps), the heaviest thing the screens
    do. Raises ImportError if ``app.machine.runtime`` (the machine loop) is not there."""
    import importlib

    importlib.import_module("app.machine.runtime")
    from app.machine import commands as cmd
    from app.machine.process_link import ProcessMachineLink
    from app.machine.states import MachineState

    base = config if config is not None else lateness_config()
    with tempfile.TemporaryDirectory() as tmp:
        path = db_path if db_path is not None else Path(tmp) / "bench.sqlite3"
        link = ProcessMachineLink.start(base, path, realtime_priority=realtime_priority)
        gui: dict[str, Any] = {}
        tally = _CycleTally(None)
        try:
            first = link.wait_for_snapshot(20.0)
            if first is None:
                raise RuntimeError("the machine process sent no snapshot")
            link.send(cmd.SelectRecipe(1))
            link.send(cmd.Home())
            homing_end = time.monotonic() + 120.0
            while time.monotonic() < homing_end:  # not counted in duration_s
                snap = link.latest()
                if (
                    snap is not None
                    and snap.state is MachineState.READY
                    and snap.all_homed
                    and time.monotonic() > homing_end - 119.0
                ):
                    break
                time.sleep(0.05)
            tally = _CycleTally(first.state)

            def drive_cycles() -> None:
                snap = link.latest()
                if snap is None:
                    return
                now = time.monotonic()
                if snap.state is MachineState.READY and now - tally.started_s > 1.0:
                    link.send(cmd.Start())
                    tally.started_s = now
                if tally.last is MachineState.AUTOMATIC and snap.state is not tally.last:
                    if snap.state is MachineState.READY:
                        tally.cycles += 1
                    else:
                        tally.alarms += 1
                tally.last = snap.state

            if with_gui:
                gui = _run_with_gui(link, duration_s, drive_cycles, path)
            else:
                end = time.monotonic() + duration_s
                while time.monotonic() < end:
                    drive_cycles()
                    time.sleep(0.05)
        finally:
            link.close()
        stats: dict[str, Any] = dict(link.lateness)
    stats["cycles"] = tally.cycles
    stats["alarms"] = tally.alarms
    stats["gui"] = gui.get("what", "none")
    stats["gui_fps"] = gui.get("fps", 0.0)
    return stats


def _run_with_gui(link: Any, duration_s: float, tick: Any, db_path: Path) -> dict[str, Any]:
    import os

    if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    import pyqtgraph as pg
    from PySide6.QtCore import QTimer
    from PySide6.QtWidgets import QApplication

    app = QApplication.instance() or QApplication([])
    what = []
    window = None
    try:
        from app.data.database import Database
        from app.screens.i18n import LanguageManager
        from app.screens.main_window import MainWindow

        database = Database.open(db_path)
        window = MainWindow(link, database, LanguageManager())
        window.resize(800, 600)
        window.show()
        what.append("operator main window")
    except Exception as exc:
        what.append(f"(main window not available: {type(exc).__name__}: {exc})")
    plot = pg.PlotWidget()
    plot.resize(800, 400)
    plot.show()
    points = 7500
    data = np.zeros((3, points))
    curves = [plot.plot(pen=pg.mkPen(c)) for c in ("r", "g", "b")]
    what.append("live plot 3x7500 points at 30 fps")
    frames = 0

    def redraw() -> None:
        nonlocal frames
        tick()
        snap = link.latest()
        if snap is not None:
            data[:, :-1] = data[:, 1:]
            data[:, -1] = [a.position for a in snap.axes[:3]]
        for curve, row in zip(curves, data, strict=True):
            curve.setData(row)
        frames += 1

    timer = QTimer()
    timer.timeout.connect(redraw)
    timer.start(33)
    t0 = time.monotonic()
    QTimer.singleShot(int(duration_s * 1000), app.quit)
    app.exec()
    timer.stop()
    elapsed = time.monotonic() - t0
    plot.close()
    if window is not None:
        window.close()
    return {"what": " + ".join(what), "fps": frames / elapsed if elapsed > 0 else 0.0}


# -- output ----------------------------------------------------------------------------------


def print_stave_tables(rows: list[dict[str, Any]]) -> None:
    print(f"\nCutting time and cycle (feed {rows[0]['feed']:.0f} mm/s)")
    print(
        f"{'stave':42} {'A/bound':>8} {'B/bound':>8} {'A/jerk':>7} {'B/jerk':>7} "
        f"{'motion s':>9} {'cycle s':>8} {'of 90 s':>7}"
    )
    for r in rows:
        print(
            f"{r['stave']:42} {r['ratio_a'][0]:8.4f} {r['ratio_b'][0]:8.4f} "
            f"{r['ratio_a'][1]:7.4f} {r['ratio_b'][1]:7.4f} {r['motion_s']:9.2f} "
            f"{r['cycle_s']:8.2f} {r['cycle_s'] / CYCLE_REQUIREMENT_S:7.1%}"
        )
    print("\nSetpoint stream at 4 ms, finite differences / limit (worst axis)")
    print(f"{'stave':42} {'v':>8} {'a':>8} {'j':>8} {'j@steps':>8}")
    for r in rows:
        print(
            f"{r['stave']:42} {r['v']:8.5f} {r['a']:8.5f} {r['j']:7.5f}{r['j_axis']} "
            f"{r['j_steps']:8.5f}"
        )
    print("\nDistance from the exact tool path while cutting, mm; planning time")
    print(
        f"{'stave':42} {'setpoint':>9} {'chord':>9} {'sim board':>9} {'sim cut':>9} "
        f"{'plan ms':>8} {'max ms':>7} {'keep-out us':>11}"
    )
    for r in rows:
        sim = r["sim"]
        board, whole = (
            ("    n/a", "    n/a") if sim is None else (f"{sim[0]:9.5f}", f"{sim[1]:9.5f}")
        )
        print(
            f"{r['stave']:42} {r['setpoint_mm']:9.2e} {r['chord_mm']:9.2e} {board:>9} "
            f"{whole:>9} {r['plan_ms']:8.2f} {r['plan_max_ms']:7.2f} {r['keep_out_us']:11.1f}"
        )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else "")
    parser.add_argument(
        "--lateness-s",
        type=float,
        default=60.0,
        help="seconds of each lateness run (0 skips the lateness part)",
    )
    parser.add_argument(
        "--no-sim", action="store_true", help="skip the simulated drives (actual path figure)"
    )
    parser.add_argument(
        "--families-only", action="store_true", help="only the side-profile family table"
    )
    args = parser.parse_args(argv)

    config = parse_config({})
    limits = MotionLimits.from_axes(config.axes, config.process.feed_mm_s)
    if args.families_only:
        print_family_table(family_rows(config, limits))
        return 0
    rows = []
    for stave in REFERENCE_STAVES:
        figures = stave_figures(stave, config, limits, simulate=not args.no_sim)
        figures["feed"] = limits.feed_mm_s
        rows.append(figures)
        print(f"  planned and ran {stave.label}", file=sys.stderr)
    print_stave_tables(rows)
    print_family_table(family_rows(config, limits))

    print("\nExecutor lateness at 4 ms (machine process on the simulation)")
    if args.lateness_s <= 0:
        print("  skipped (--lateness-s 0)")
        return 0
    try:
        import importlib.util

        if importlib.util.find_spec("app.machine.runtime") is None:
            raise ImportError("app.machine.runtime")
    except ImportError:
        print("  skipped: app.machine.runtime (the machine loop) does not exist yet")
        return 0
    import os

    fifo = _fifo_permitted()
    print(f"  SCHED_FIFO is {'' if fifo else 'NOT '}permitted here; {os.cpu_count()} CPUs")
    print(
        f"{'run':40} {'periods':>8} {'p50 ms':>7} {'p99 ms':>7} {'max ms':>7} "
        f"{'overruns':>8} {'cycles':>6} {'alarms':>6}"
    )
    gui_text = ""
    for realtime in (True, False) if fifo else (False,):
        for with_gui in (False, True):
            stats = measure_lateness(args.lateness_s, with_gui=with_gui, realtime_priority=realtime)
            policy = "SCHED_FIFO" if realtime else "SCHED_OTHER"
            what = f"GUI plotting, {stats['gui_fps']:.0f} fps" if with_gui else "alone"
            print(
                f"{policy + ', ' + what:40} {stats.get('periods', 0):8.0f} "
                f"{stats.get('p50_ms', math.nan):7.3f} {stats.get('p99_ms', math.nan):7.3f} "
                f"{stats.get('max_ms', math.nan):7.3f} {stats.get('overruns', 0):8.0f} "
                f"{stats['cycles']:6d} {stats['alarms']:6d}"
            )
            if with_gui:
                gui_text = stats["gui"]
    print(f"  GUI: {gui_text}")
    return 0


def _fifo_permitted() -> bool:
    import os

    try:
        policy = os.sched_getscheduler(0)
        param = os.sched_getparam(0)
        os.sched_setscheduler(0, os.SCHED_FIFO, os.sched_param(1))
        os.sched_setscheduler(0, policy, param)
        return True
    except (AttributeError, PermissionError, OSError):
        return False


if __name__ == "__main__":
    raise SystemExit(main())
