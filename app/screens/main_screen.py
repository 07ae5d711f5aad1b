"""Main screen (automatic mode, the default after power-on; docs/MACHINE.md section 5).

Recipe selection (previous/next with its number, or a list), big Start and Stop, Home and
Reset, the axes in big digits (unhomed positions look different), the I/O strip, piece
counters, the board's width once measured, the last cycle's time with its wait for the board
apart, the cycle panel (step; cycle time, wait, remaining; distance to go and path speed, or
during homing the axes done and to come; progress only along the plan; the feed override
while a cycle runs), the live plan view, the barrel panel, the last cycle's step times.

Everything shown comes computed from the snapshot: the screen formats figures and never
derives motion from them (distance, speed, progress are the machine's).

Why Start and Stop are enabled from ``snapshot.allowed``: the machine decides what is allowed
(one rule for the buttons and the machine); a disabled Start says why in words below it, so
an operator never presses a dead button wondering.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QProgressBar,
    QPushButton,
    QSizePolicy,
    QStackedWidget,
    QVBoxLayout,
    QWidget,
)

from app.data.recipe import BarrelType, Recipe
from app.machine.commands import (
    Abandon,
    Home,
    LoadBoard,
    Reset,
    Resume,
    SelectRecipe,
    SetFeedOverride,
    Start,
    Stop,
)
from app.machine.snapshot import HomingView, MachineSnapshot
from app.machine.states import MachineState
from app.screens.barrel_panel import BarrelPanel
from app.screens.base import Screen, ScreenContext, refusal
from app.screens.formatting import format_duration, format_optional
from app.screens.recipe_chooser import RecipeChooser
from app.screens.texts import step_text
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay
from app.screens.widgets.feed_override import FeedOverride
from app.screens.widgets.io_strip import LAMP_PX as IO_LAMP_PX
from app.screens.widgets.io_strip import IoStrip
from app.screens.widgets.plan_view import PlanView
from app.screens.widgets.readouts import (
    AxisReadout,
    ElidedLinesLabel,
    ValueTile,
    set_text,
    styled_label,
)
from app.screens.widgets.step_times_bar import StepTimesBar

LEFT_WIDTH_PX = 268
FIGURE_SAMPLE = "8888 mm/s"  # the widest figure of the cycle panel


class MainScreen(Screen):
    key = "main"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.recipes: list[Recipe] = []

        # -- left column: recipe, start/stop, home/reset ----------------------------------
        recipe_panel = QFrame()
        recipe_panel.setObjectName("panel")
        self.recipe_caption = styled_label("", "caption")
        self.prev_button = touch_button("prevRecipe")
        self.prev_button.setText("◀")
        self.next_button = touch_button("nextRecipe")
        self.next_button.setText("▶")
        # The recipe's number between the arrows is a button that opens the list; the name
        # is shown in full below.
        self.list_button = touch_button("recipeList", "recipe")
        self.number_label = styled_label("—", "bigvalue", "recipeNumber")
        self.number_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.number_label.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
        inside = QVBoxLayout(self.list_button)
        inside.setContentsMargins(2, 2, 2, 2)
        inside.addWidget(self.number_label)
        # Two lines kept whatever the name: a long one ends in an ellipsis and never pushes
        # START, STOP, Home and Reset down.
        self.name_label = ElidedLinesLabel("value", "recipeName")
        self.name_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        for arrow in (self.prev_button, self.next_button):
            arrow.setProperty("kind", "arrow")
        stepper = QHBoxLayout()
        stepper.setSpacing(6)
        stepper.addWidget(self.prev_button)
        stepper.addWidget(self.list_button, 1)
        stepper.addWidget(self.next_button)
        recipe_layout = QVBoxLayout(recipe_panel)
        recipe_layout.setContentsMargins(8, 4, 8, 8)
        recipe_layout.setSpacing(4)
        recipe_layout.addWidget(self.recipe_caption)
        recipe_layout.addLayout(stepper)
        recipe_layout.addWidget(self.name_label)
        self.prev_button.clicked.connect(lambda: self.step_recipe(-1))
        self.next_button.clicked.connect(lambda: self.step_recipe(+1))
        self.list_button.clicked.connect(self.open_recipe_list)

        self.start_button = touch_button("startButton", "start")
        self.stop_button = touch_button("stopButton", "stop")
        self.start_button.clicked.connect(self.press_start)
        self.stop_button.clicked.connect(lambda: self.context.send(Stop()))
        self.hint_label = styled_label("", "message", "startHint")
        self.hint_label.setWordWrap(True)
        self.home_button = touch_button("homeButton", "primary")
        self.reset_button = touch_button("resetButton", "primary")
        self.home_button.clicked.connect(lambda: self.context.send(Home()))
        self.reset_button.clicked.connect(lambda: self.context.send(Reset()))
        self.load_button = touch_button("loadBoardButton")
        self.load_button.clicked.connect(lambda: self.context.send(LoadBoard()))
        row = QVBoxLayout()  # one above the other: full width for the longer languages
        row.setSpacing(8)
        row.addWidget(self.home_button)
        row.addWidget(self.reset_button)

        left = QVBoxLayout()
        left.setSpacing(8)
        left.addWidget(recipe_panel)
        left.addWidget(self.start_button)
        left.addWidget(self.stop_button)
        left.addLayout(row)
        # One place under the buttons: why Start is refused while idle, or, on the simulated
        # machine while a cycle runs (no hint then), the operator's hands putting a board in.
        self.hint_stack = QStackedWidget()
        self.hint_label.setAlignment(Qt.AlignmentFlag.AlignTop | Qt.AlignmentFlag.AlignLeft)
        self.hint_stack.addWidget(self.hint_label)
        load_page = QWidget()
        load_layout = QVBoxLayout(load_page)
        load_layout.setContentsMargins(0, 0, 0, 0)
        load_layout.addWidget(self.load_button)
        load_layout.addStretch(1)
        self.hint_stack.addWidget(load_page)
        left.addWidget(self.hint_stack, 1)
        left_widget = QWidget()
        left_widget.setLayout(left)
        left_widget.setFixedWidth(LEFT_WIDTH_PX)
        self.left_widget = left_widget

        # -- right: positions, counters, cycle, plan ----------------------------------------
        self.axis_x = AxisReadout("X", "mm")
        self.axis_y = AxisReadout("Y", "mm")
        self.axis_z = AxisReadout("Z", "°")
        axes = QHBoxLayout()
        axes.setSpacing(8)
        for readout in (self.axis_x, self.axis_y, self.axis_z):
            axes.addWidget(readout, 1)

        self.shift_tile = ValueTile(name="piecesShift", role="bigvalue")
        self.total_tile = ValueTile(name="piecesTotal", role="bigvalue")
        self.width_tile = ValueTile(name="lastWidth")
        self.cycle_time_tile = ValueTile(name="lastCycleTime")
        # The last cycle's wait for its board, beside its time (not in it).
        self.last_wait_label = styled_label("", "caption", "lastWait")
        self.cycle_time_tile.add_note(self.last_wait_label)
        self.reset_shift_button = touch_button("resetShiftButton")
        self.reset_shift_button.clicked.connect(self.confirm_reset_shift)
        counters = QHBoxLayout()
        counters.setSpacing(8)
        for tile in (self.shift_tile, self.total_tile, self.width_tile):
            counters.addWidget(tile, 2)
        counters.addWidget(self.cycle_time_tile, 3)
        counters.addWidget(self.reset_shift_button, 2)

        # The cycle (or the homing) now: its step, its times, the path left and the speed,
        # progress where the step has a known length, and the feed override.
        cycle_panel = QFrame()
        cycle_panel.setObjectName("panel")
        self.step_label = ElidedLinesLabel("value", "cycleStep", lines=1)
        self.step_label.never_widen()
        figures = QGridLayout()
        figures.setHorizontalSpacing(8)
        figures.setVerticalSpacing(0)
        # Three figures in two rows: the cycle's times, then the path (or, homing, the axes).
        self.elapsed_caption = styled_label("", "caption")
        self.elapsed_label = styled_label("—", "figure", "elapsed")
        self.waited_caption = styled_label("", "caption")
        self.waited_label = styled_label("—", "figure", "waited")
        self.remaining_caption = styled_label("", "caption")
        self.remaining_label = styled_label("—", "figure", "remaining")
        self.move_caption = styled_label("", "caption")
        self.move_label = styled_label("—", "figure", "moveToGo")
        self.phase_caption = styled_label("", "caption")
        self.phase_label = styled_label("—", "figure", "phaseToGo")
        self.speed_caption = styled_label("", "caption")
        self.speed_label = styled_label("—", "figure", "pathSpeed")
        pairs = (
            (self.elapsed_caption, self.elapsed_label),
            (self.waited_caption, self.waited_label),
            (self.remaining_caption, self.remaining_label),
            (self.move_caption, self.move_label),
            (self.phase_caption, self.phase_label),
            (self.speed_caption, self.speed_label),
        )
        for index, (caption, value) in enumerate(pairs):
            line, column = divmod(index, 3)
            figures.addWidget(caption, 2 * line, column)
            figures.addWidget(value, 2 * line + 1, column)
        for column in range(3):
            figures.setColumnStretch(column, 1)
        self._figure_values = tuple(value for _caption, value in pairs)
        self._fit_figures()
        self.progress = QProgressBar()
        self.progress.setObjectName("cycleProgress")
        self.progress.setRange(0, 1000)
        self.progress.setTextVisible(False)
        self._keep_place(self.progress)
        self.feed_override = FeedOverride()
        self.feed_override.requested.connect(
            lambda percent: self.context.send(SetFeedOverride(percent))
        )
        self._keep_place(self.feed_override)
        cycle_layout = QVBoxLayout(cycle_panel)
        cycle_layout.setContentsMargins(10, 4, 10, 6)
        cycle_layout.setSpacing(4)
        cycle_layout.addWidget(self.step_label)
        cycle_layout.addLayout(figures)
        cycle_layout.addWidget(self.progress)
        cycle_layout.addStretch(1)
        cycle_layout.addWidget(self.feed_override)

        self.step_times_caption = styled_label("", "caption")
        self.step_times_bar = StepTimesBar()
        step_times = QHBoxLayout()
        step_times.setSpacing(8)
        step_times.addWidget(self.step_times_caption)
        step_times.addWidget(self.step_times_bar, 1)

        self.io_strip = IoStrip()
        self.io_strip.button.clicked.connect(lambda: self.context.navigate("io"))

        self.plan_view = PlanView()
        self.plan_view.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self.plan_view.setMinimumHeight(100)  # the stave is long and flat: 100 px show it

        right = QVBoxLayout()
        right.setSpacing(8)
        right.addLayout(axes)
        right.addWidget(self.io_strip)
        right.addLayout(counters)
        self.barrel_panel = BarrelPanel(context)
        views = QVBoxLayout()  # the plan over the barrel being raised
        views.setSpacing(8)
        views.addWidget(self.plan_view, 1)
        views.addWidget(self.barrel_panel, 1)  # on a larger panel the drawing grows too
        middle = QHBoxLayout()
        middle.setSpacing(8)
        # The cycle panel at about its own width; the plan and the barrel (whose closing
        # question's two answers are the widest row) take the rest.
        middle.addWidget(cycle_panel, 4)
        middle.addLayout(views, 5)
        right.addLayout(middle, 1)
        right.addLayout(step_times)

        layout = QHBoxLayout(self)
        layout.setContentsMargins(8, 6, 8, 6)  # at 1024x768 every pixel of height counts
        layout.setSpacing(10)
        layout.addWidget(left_widget)
        layout.addLayout(right, 1)
        self.retranslate()
        self.reload_recipes()

    # -- texts ----------------------------------------------------------------------------------

    def title(self) -> str:
        return self.tr("Main")

    def _set_load_text(self, board_on_table: bool) -> None:
        """The simulated operator's hands: a board on the table is replaced (LoadBoard takes
        it off first), an empty table gets one."""
        if board_on_table:
            set_text(self.load_button, self.tr("Replace the board\n(simulation)"))
        else:
            set_text(self.load_button, self.tr("Put a board in\n(simulation)"))

    def _fit_figures(self) -> None:
        """Each figure as wide as its widest value ("8888 mm/s"), whatever it shows now: the
        figures change ten times a second, and the panel must not change width with them."""
        for label in self._figure_values:
            label.ensurePolished()
            label.setMinimumWidth(label.fontMetrics().horizontalAdvance(FIGURE_SAMPLE) + 2)

    @staticmethod
    def _keep_place(widget: QWidget) -> None:
        """Hidden, ``widget`` keeps its place: nothing around it moves when it shows."""
        policy = widget.sizePolicy()
        policy.setRetainSizeWhenHidden(True)
        widget.setSizePolicy(policy)

    def retranslate(self) -> None:
        self.recipe_caption.setText(self.tr("Recipe"))
        self.list_button.setToolTip(self.tr("Choose recipe…"))
        self.prev_button.setToolTip(self.tr("Previous recipe"))
        self.next_button.setToolTip(self.tr("Next recipe"))
        self.start_button.setText(self.tr("▶  START"))
        self.stop_button.setText(self.tr("■  STOP"))
        self.home_button.setText(self.tr("Home"))
        self.reset_button.setText(self.tr("Reset"))
        self._set_load_text(self.snapshot is not None and self.snapshot.inputs.part_present)
        self.reset_shift_button.setText(self.tr("New\nshift"))
        self.shift_tile.set_caption(self.tr("Pieces this shift"))
        self.total_tile.set_caption(self.tr("Pieces total"))
        self.width_tile.set_caption(self.tr("Last width"))
        self.cycle_time_tile.set_caption(self.tr("Last cycle"))
        self._show_width(self.snapshot)
        self.elapsed_caption.setText(self.tr("Cycle"))
        self.waited_caption.setText(self.tr("Waited"))
        self.remaining_caption.setText(self.tr("Remaining"))
        self.feed_override.retranslate()
        self.io_strip.button.setToolTip(self.tr("All inputs and outputs"))
        self.io_strip.retranslate()
        self.step_times_caption.setText(self.tr("Last cycle by step"))
        for readout in (self.axis_x, self.axis_y, self.axis_z):
            readout.set_not_homed_text(self.tr("NOT HOMED"))
        self._show_recipe_number()
        self.barrel_panel.retranslate()
        if self.snapshot is not None:
            self._show_cycle(self.snapshot)

    # -- recipes -------------------------------------------------------------------------------

    def reload_recipes(self) -> None:
        """Read the recipe list again (the Recipes screen may have changed it)."""
        self.recipes = sorted(
            self.context.database.list_recipes(), key=lambda r: r.id if r.id is not None else 0
        )
        self._show_recipe_number()

    def _current_index(self) -> int | None:
        snapshot = self.snapshot
        if snapshot is None or snapshot.recipe_id is None:
            return None
        for index, recipe in enumerate(self.recipes):
            if recipe.id == snapshot.recipe_id:
                return index
        return None

    def step_recipe(self, delta: int) -> None:
        """Previous (-1) or next (+1) recipe of the list, wrapping around."""
        if not self.recipes:
            self.context.notify(self.tr("There are no recipes yet: create one on Recipes."))
            return
        index = self._current_index()
        if index is None:
            index = 0 if delta > 0 else len(self.recipes) - 1
        else:
            index = (index + delta) % len(self.recipes)
        recipe_id = self.recipes[index].id
        if recipe_id is not None:
            self.context.send(SelectRecipe(recipe_id))

    def open_recipe_list(self) -> None:
        self.reload_recipes()
        overlay = RecipeChooser(
            self.recipes,
            self.snapshot.recipe_id if self.snapshot else None,
            self.context.open,
            self.context.keyboard_layout,
        )
        overlay.chosen.connect(lambda recipe_id: self.context.send(SelectRecipe(recipe_id)))
        self.context.open(overlay)

    def _board_choices(self) -> list[tuple[str, object]]:
        """Resume / Abandon, where the machine allows them (a board is partly cut)."""
        allowed = self.snapshot.allowed if self.snapshot is not None else {}
        choices: list[tuple[str, object]] = []
        if "Resume" in allowed and allowed["Resume"] is None:
            choices.append((self.tr("Resume the cut"), Resume()))
        if "Abandon" in allowed and allowed["Abandon"] is None:
            choices.append((self.tr("Abandon the board"), Abandon()))
        return choices

    def press_start(self) -> None:
        """Start; with a partly cut board on the table, the choice between resuming its cut
        and abandoning it (a fresh cycle would cut through it)."""
        choices = self._board_choices()
        if not choices:
            self.context.send(Start())
            return
        overlay = ChoiceOverlay(self.tr("A board is partly cut"), choices, columns=1)
        overlay.chosen.connect(self.context.send)
        self.context.open(overlay)

    def confirm_reset_shift(self) -> None:
        overlay = ConfirmOverlay(
            self.tr("New shift"),
            self.tr(
                "Start counting the pieces of a new shift from 0? The total count is kept;"
                " the operator of the new shift then enters his name."
            ),
            self.tr("Start new shift"),
        )
        overlay.finished.connect(lambda ok: self.context.new_shift() if ok else None)
        self.context.open(overlay)

    def _show_recipe_number(self) -> None:
        snapshot = self.snapshot
        if snapshot is None or snapshot.recipe_id is None:
            set_text(self.number_label, "—")
            set_text(self.name_label, self.tr("No recipe selected"))
            return
        set_text(self.number_label, self.tr("No. %1").replace("%1", str(snapshot.recipe_id)))
        set_text(self.name_label, snapshot.recipe_name)

    # -- machine ---------------------------------------------------------------------------------

    def activated(self) -> None:
        self.reload_recipes()

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        previous = self.snapshot
        self.snapshot = snapshot
        if previous is not None and previous.recipe_id != snapshot.recipe_id:
            self.plan_view.set_plan(None)
        if (
            force
            or previous is None
            or previous.recipe_id != snapshot.recipe_id
            or previous.recipe_name != snapshot.recipe_name
        ):
            if snapshot.recipe_id is not None and self._current_index() is None:
                self.reload_recipes()
            self._show_recipe_number()
        allowed = snapshot.allowed
        self._enable(self.start_button, "Start")
        if self._board_choices():
            self.start_button.setEnabled(True)
        self._enable(self.stop_button, "Stop")
        self._enable(self.home_button, "Home")
        self._enable(self.reset_button, "Reset")
        select_reason = refusal(snapshot, "SelectRecipe")
        for button in (self.prev_button, self.next_button, self.list_button):
            button.setEnabled(not select_reason)
            button.setToolTip(select_reason)
        simulation = "InjectFault" in allowed and not allowed["InjectFault"]
        hands = simulation and snapshot.state is MachineState.AUTOMATIC
        self.hint_stack.setCurrentIndex(1 if hands else 0)
        self._set_load_text(snapshot.inputs.part_present)
        self.load_button.setEnabled(
            simulation and snapshot.state is MachineState.AUTOMATIC and not allowed["LoadBoard"]
        )
        self._show_hint(snapshot)

        for readout in (self.axis_x, self.axis_y, self.axis_z):
            try:
                axis = snapshot.axis(readout.axis)
            except KeyError:
                continue
            readout.set_position(axis.position, axis.homed, axis.faulted)

        self.shift_tile.set_value(str(snapshot.pieces_shift))
        self.total_tile.set_value(str(snapshot.pieces_total))
        self._show_width(snapshot)
        self.cycle_time_tile.set_value(format_duration(snapshot.last_work_time_s))
        wait = format_duration(snapshot.last_wait_s)
        shown = wait not in ("—", format_duration(0.0))  # no note for no wait
        set_text(self.last_wait_label, self.tr("+%1 waiting").replace("%1", wait) if shown else "")
        self.step_times_bar.set_step_times(snapshot.last_step_times_s)
        self._show_cycle(snapshot)

        self.io_strip.show_inputs(snapshot.inputs, force)
        self._update_plan(snapshot)
        self._update_barrel(snapshot)

    def _show_width(self, snapshot: MachineSnapshot | None) -> None:
        """The board being cut as soon as the gauge has measured it; else the last one's."""
        measured = snapshot.cycle.width_mm if snapshot is not None else None
        if measured is not None:
            self.width_tile.set_caption(self.tr("Board width"))
            self.width_tile.set_value(format_optional(measured, 1, "mm"))
            return
        self.width_tile.set_caption(self.tr("Last width"))
        last = snapshot.last_width_mm if snapshot is not None else None
        self.width_tile.set_value(format_optional(last, 1, "mm"))

    def _show_cycle(self, snapshot: MachineSnapshot) -> None:
        """The cycle panel: the step, its figures, the progress where the step has a known
        length (never for a wait or a stop), and the feed override while a cycle runs."""
        cycle = snapshot.cycle
        homing = snapshot.homing if cycle.step is None else None
        self.feed_override.setVisible(
            snapshot.state in (MachineState.AUTOMATIC, MachineState.STOPPING)
        )
        self.feed_override.show_percent(snapshot.feed_override_pct)
        if cycle.finished_board_on_table:
            set_text(self.step_label, self.tr("Take the finished board off"))
        elif cycle.step is not None:
            set_text(self.step_label, step_text(cycle.step))
        elif homing is not None:
            set_text(self.step_label, self._homing_text(homing))
        else:
            set_text(self.step_label, self.tr("No cycle running"))
        running = cycle.step is not None
        set_text(self.elapsed_label, format_duration(cycle.working_s) if running else "—")
        set_text(self.waited_label, format_duration(cycle.waited_s) if running else "—")
        # Remaining: known once the path is planned (to rest while stopping), not before.
        known = running and (cycle.progress is not None or cycle.remaining_s > 0.0)
        set_text(self.remaining_label, format_duration(cycle.remaining_s) if known else "—")
        if homing is not None:
            self._show_homing_axes(homing)
        else:
            self.move_caption.setText(self.tr("Move to go"))
            self.phase_caption.setText(self.tr("Step to go"))
            self.speed_caption.setText(self.tr("Path speed"))
            set_text(self.move_label, format_optional(cycle.move_to_go_mm, 0, "mm"))
            set_text(self.phase_label, format_optional(cycle.phase_to_go_mm, 0, "mm"))
            set_text(self.speed_label, format_optional(cycle.path_velocity_mm_s, 0, "mm/s"))
        self.progress.setVisible(cycle.progress is not None)
        if cycle.progress is not None:
            self.progress.setValue(round(1000 * cycle.progress))

    def _homing_text(self, homing: HomingView) -> str:
        if homing.clearing:
            return self.tr("Moving clear of the board")
        if homing.current:
            return self.tr("Homing axis %1").replace("%1", homing.current)
        return self.tr("Homing done")

    def _show_homing_axes(self, homing: HomingView) -> None:
        """The second row of figures names the axes homing in their order: done, homing
        now, or still to come."""
        slots = (
            (self.move_caption, self.move_label),
            (self.phase_caption, self.phase_label),
            (self.speed_caption, self.speed_label),
        )
        for index, (caption, value) in enumerate(slots):
            if index >= len(homing.axes):
                caption.setText("")
                set_text(value, "")
                continue
            axis = homing.axes[index]
            caption.setText(self.tr("Axis %1").replace("%1", axis))
            if axis in homing.done:
                set_text(value, self.tr("homed ✓"))
            elif axis == homing.current and not homing.clearing:
                set_text(value, self.tr("homing…"))
            else:
                set_text(value, self.tr("waiting"))

    def _update_barrel(self, snapshot: MachineSnapshot) -> None:
        """The barrel panel, while the selected recipe makes barrels or one is raised."""
        index = self._current_index()
        barrels = index is not None and self.recipes[index].barrel_type is not BarrelType.FIXED_TILT
        self.barrel_panel.setVisible(barrels or snapshot.barrel is not None)
        self.barrel_panel.show_barrel(snapshot.barrel, snapshot)

    def apply_scale(self, scale: float) -> None:
        self.left_widget.setFixedWidth(round(LEFT_WIDTH_PX * scale))
        self.plan_view.set_scale(scale)
        self.io_strip.set_lamp_diameter(round(IO_LAMP_PX * scale))
        self.step_times_bar.set_scale(scale)
        self._fit_figures()

    def _enable(self, button: QPushButton, command: str) -> None:
        reason = refusal(self.snapshot, command)
        enabled = not reason
        if button.isEnabled() != enabled:
            button.setEnabled(enabled)
        if button.toolTip() != reason:
            button.setToolTip(reason)

    def _show_hint(self, snapshot: MachineSnapshot) -> None:
        """Under the buttons: why Start is not possible, when the machine is idle."""
        if snapshot.state in (MachineState.AUTOMATIC, MachineState.HOMING, MachineState.STOPPING):
            set_text(self.hint_label, "")
            return
        reason = refusal(snapshot, "Start")
        set_text(self.hint_label, reason)

    def _update_plan(self, snapshot: MachineSnapshot) -> None:
        """Draw a new plan once it has arrived (asked again on every snapshot until then);
        the last plan stays shown between boards until another recipe is selected. The
        cutter moves on every snapshot, i.e. at most at the poller's 30 Hz."""
        if snapshot.plan_id and snapshot.plan_id != self.plan_view.plan_id:
            plan = self.context.link.plan(snapshot.plan_id)
            if plan is not None:
                self.plan_view.set_plan(plan)
        try:
            x = snapshot.axis("X").position
            y = snapshot.axis("Y").position
        except KeyError:
            return
        self.plan_view.set_cutter(x, y)
