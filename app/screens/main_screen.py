"""Main screen (automatic mode, the default after power-on; docs/MACHINE.md section 5).

Recipe selection (previous/next with its number, or a list), big Start and Stop, Home and
Reset, the axes in big digits (unhomed positions look different), piece counters, the last
width and cycle time, elapsed and remaining time of the running cycle, and the live plan view.

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
    QVBoxLayout,
    QWidget,
)

from app.data.recipe import BarrelType, Recipe
from app.machine.commands import (
    Abandon,
    Home,
    LoadBoard,
    Reset,
    ResetShiftCounter,
    Resume,
    SelectRecipe,
    Start,
    Stop,
)
from app.machine.snapshot import MachineSnapshot
from app.machine.states import MachineState
from app.screens.barrel_panel import BarrelPanel
from app.screens.base import Screen, ScreenContext, refusal
from app.screens.formatting import format_duration, format_optional
from app.screens.recipe_chooser import RecipeChooser
from app.screens.texts import step_text
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay
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
        left.addWidget(self.hint_label)
        left.addStretch(1)
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
        self.reset_shift_button = touch_button("resetShiftButton")
        self.reset_shift_button.clicked.connect(self.confirm_reset_shift)
        counters = QGridLayout()
        counters.setSpacing(8)
        counters.addWidget(self.shift_tile, 0, 0)
        counters.addWidget(self.total_tile, 0, 1)
        counters.addWidget(self.width_tile, 0, 2)
        counters.addWidget(self.cycle_time_tile, 0, 3)
        counters.addWidget(self.reset_shift_button, 0, 4)

        cycle_panel = QFrame()
        cycle_panel.setObjectName("panel")
        self.step_label = styled_label("", "value", "cycleStep")
        self.elapsed_caption = styled_label("", "caption")
        self.elapsed_label = styled_label("—", "value", "elapsed")
        self.remaining_caption = styled_label("", "caption")
        self.remaining_label = styled_label("—", "value", "remaining")
        self.progress = QProgressBar()
        self.progress.setObjectName("cycleProgress")
        self.progress.setRange(0, 1000)
        self.progress.setTextVisible(False)
        cycle_layout = QGridLayout(cycle_panel)
        cycle_layout.setContentsMargins(10, 4, 10, 6)
        cycle_layout.setVerticalSpacing(2)
        cycle_layout.addWidget(self.step_label, 0, 0, 2, 1)
        cycle_layout.addWidget(self.elapsed_caption, 0, 1)
        cycle_layout.addWidget(self.elapsed_label, 1, 1)
        cycle_layout.addWidget(self.remaining_caption, 0, 2)
        cycle_layout.addWidget(self.remaining_label, 1, 2)
        cycle_layout.addWidget(self.load_button, 0, 3, 2, 1)
        cycle_layout.addWidget(self.progress, 2, 0, 1, 4)
        self.step_times_caption = styled_label("", "caption")
        self.step_times_bar = StepTimesBar()
        cycle_layout.addWidget(self.step_times_caption, 3, 0, 1, 4)
        cycle_layout.addWidget(self.step_times_bar, 4, 0, 1, 4)
        cycle_layout.setColumnStretch(0, 1)

        self.io_strip = IoStrip()
        self.io_strip.button.clicked.connect(lambda: self.context.navigate("io"))

        self.plan_view = PlanView()
        self.plan_view.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self.plan_view.setMinimumHeight(150)

        right = QVBoxLayout()
        right.setSpacing(8)
        right.addLayout(axes)
        right.addWidget(self.io_strip)
        right.addLayout(counters)
        right.addWidget(cycle_panel)
        self.barrel_panel = BarrelPanel(context)
        views = QHBoxLayout()
        views.setSpacing(8)
        views.addWidget(self.plan_view, 1)
        views.addWidget(self.barrel_panel, 1)
        right.addLayout(views, 1)

        layout = QHBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
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
        self.elapsed_caption.setText(self.tr("Elapsed"))
        self.remaining_caption.setText(self.tr("Remaining"))
        self.io_strip.button.setToolTip(self.tr("All inputs and outputs"))
        self.io_strip.retranslate()
        self.step_times_caption.setText(self.tr("Last cycle by step"))
        for readout in (self.axis_x, self.axis_y, self.axis_z):
            readout.set_not_homed_text(self.tr("NOT HOMED"))
        self._show_recipe_number()
        self.barrel_panel.retranslate()

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
            self.tr("Start counting the pieces of a new shift from 0? The total count is kept."),
            self.tr("Start new shift"),
        )
        overlay.finished.connect(lambda ok: self.context.send(ResetShiftCounter()) if ok else None)
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
        self.load_button.setVisible(simulation)
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
        self.width_tile.set_value(format_optional(snapshot.last_width_mm, 1, "mm"))
        self.cycle_time_tile.set_value(
            format_duration(snapshot.last_cycle_time_s) if snapshot.last_cycle_time_s else "—"
        )

        self.step_times_bar.set_step_times(snapshot.last_step_times_s)
        cycle = snapshot.cycle
        if cycle.finished_board_on_table:
            set_text(self.step_label, self.tr("Take the finished board off"))
        elif cycle.step is not None:
            set_text(self.step_label, step_text(cycle.step))
            set_text(self.elapsed_label, format_duration(cycle.elapsed_s))
            set_text(self.remaining_label, format_duration(cycle.remaining_s))
            total = cycle.elapsed_s + cycle.remaining_s
            self.progress.setValue(round(1000 * cycle.elapsed_s / total) if total > 0 else 0)
        else:
            set_text(self.step_label, self.tr("No cycle running"))
            set_text(self.elapsed_label, "—")
            set_text(self.remaining_label, "—")
            self.progress.setValue(0)

        self.io_strip.show_inputs(snapshot.inputs, force)
        self._update_plan(snapshot)
        self._update_barrel(snapshot)

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
