"""Words for the machine's states, steps, alarms and messages in the current language.

Why here: the machine layer speaks English identifiers and messages (it has no Qt and must
not); the screens translate them at the moment they are shown. Fixed vocabularies (states,
cycle steps, roles) are tables of ``QT_TRANSLATE_NOOP`` entries; open-ended texts from the
machine or the data layer (alarm titles, refusal reasons, parameter descriptions) are looked
up by their English text in the contexts listed in :mod:`app.screens.catalogue_strings`,
generated from those catalogues, so a new alarm or parameter shows up as a missing
translation in the tests instead of silently staying English.
"""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.data.records import AlarmEvent
from app.data.users import Role
from app.geometry.errors import FieldError
from app.machine.alarms import definition_of
from app.machine.refusals import Refusal, refusal_from_json
from app.machine.snapshot import AlarmState, AlarmView
from app.machine.states import CycleStep, MachineState


def QT_TRANSLATE_NOOP(context: str, text: str) -> str:
    """Marks ``text`` for lupdate under ``context`` and returns it unchanged, as Qt's own
    marker does; PySide6's stub declares Qt's marker as returning ``object``, so the tables
    below would lose their ``str`` type. lupdate finds the calls by this name."""
    del context
    return text


MACHINE_TEXT_CONTEXT = "MachineText"
ALARM_TEXT_CONTEXT = "AlarmText"
PARAMETER_CONTEXT = "Parameters"
RULE_TEXT_CONTEXT = "RuleText"
GENERIC_RULE_TEXT = QT_TRANSLATE_NOOP("RuleText", "This value is not allowed")
"""What a screen says of an error whose check has no words of its own (never a program's
field name)."""

_STATES: dict[MachineState, str] = {
    MachineState.POWER_UP: QT_TRANSLATE_NOOP("States", "STARTING UP"),
    MachineState.NOT_HOMED: QT_TRANSLATE_NOOP("States", "NOT HOMED"),
    MachineState.HOMING: QT_TRANSLATE_NOOP("States", "HOMING"),
    MachineState.READY: QT_TRANSLATE_NOOP("States", "READY"),
    MachineState.AUTOMATIC: QT_TRANSLATE_NOOP("States", "RUNNING"),
    MachineState.MANUAL: QT_TRANSLATE_NOOP("States", "MANUAL"),
    MachineState.STOPPING: QT_TRANSLATE_NOOP("States", "STOPPING"),
    MachineState.ERROR: QT_TRANSLATE_NOOP("States", "FAULT"),
    MachineState.EMERGENCY_STOP: QT_TRANSLATE_NOOP("States", "EMERGENCY STOP"),
}

_STEPS: dict[CycleStep, str] = {
    CycleStep.WAIT_FOR_PART: QT_TRANSLATE_NOOP("Steps", "Waiting for a board"),
    CycleStep.CENTERING: QT_TRANSLATE_NOOP("Steps", "Centering"),
    CycleStep.CLAMPING: QT_TRANSLATE_NOOP("Steps", "Clamping"),
    CycleStep.MEASURING: QT_TRANSLATE_NOOP("Steps", "Measuring the width"),
    CycleStep.RETRACTING: QT_TRANSLATE_NOOP("Steps", "Moving clear of the board"),
    CycleStep.STARTING_SPINDLE: QT_TRANSLATE_NOOP("Steps", "Starting the spindle"),
    CycleStep.CUTTING_A: QT_TRANSLATE_NOOP("Steps", "Cutting side A"),
    CycleStep.REPOSITIONING: QT_TRANSLATE_NOOP("Steps", "Repositioning and tilting"),
    CycleStep.CUTTING_B: QT_TRANSLATE_NOOP("Steps", "Cutting side B"),
    CycleStep.RETURNING: QT_TRANSLATE_NOOP("Steps", "Returning"),
    CycleStep.UNCLAMPING: QT_TRANSLATE_NOOP("Steps", "Unclamping"),
}

_ALARM_STATES: dict[AlarmState, str] = {
    AlarmState.NORMAL: QT_TRANSLATE_NOOP("AlarmStates", "normal"),
    AlarmState.ACTIVE_UNACKED: QT_TRANSLATE_NOOP("AlarmStates", "active, unacknowledged"),
    AlarmState.ACTIVE_ACKED: QT_TRANSLATE_NOOP("AlarmStates", "active, acknowledged"),
    AlarmState.RTN_UNACKED: QT_TRANSLATE_NOOP("AlarmStates", "cleared, unacknowledged"),
}

# The data layer's history states (stored as text) -> the same words.
_HISTORY_STATES: dict[str, str] = {
    "normal": QT_TRANSLATE_NOOP("AlarmStates", "normal"),
    "active_unacked": QT_TRANSLATE_NOOP("AlarmStates", "active, unacknowledged"),
    "active_acked": QT_TRANSLATE_NOOP("AlarmStates", "active, acknowledged"),
    "returned_unacked": QT_TRANSLATE_NOOP("AlarmStates", "cleared, unacknowledged"),
    "shelved": QT_TRANSLATE_NOOP("AlarmStates", "shelved"),
}

_ROLES: dict[Role, str] = {
    Role.OPERATOR: QT_TRANSLATE_NOOP("Roles", "Operator"),
    Role.TECHNICIAN: QT_TRANSLATE_NOOP("Roles", "Technician"),
    Role.SERVICE: QT_TRANSLATE_NOOP("Roles", "Service"),
}

_SEVERITIES: dict[str, str] = {
    "fault": QT_TRANSLATE_NOOP("AlarmStates", "fault"),
    "warning": QT_TRANSLATE_NOOP("AlarmStates", "warning"),
}


def _t(context: str, text: str) -> str:
    return QCoreApplication.translate(context, text)


def state_text(state: MachineState | None) -> str:
    if state is None:
        return QCoreApplication.translate("States", "NO MACHINE")
    return _t("States", _STATES[state])


def step_text(step: CycleStep | None) -> str:
    if step is None:
        return ""
    return _t("Steps", _STEPS[step])


def alarm_state_text(state: AlarmState) -> str:
    return _t("AlarmStates", _ALARM_STATES[state])


def history_state_text(value: str) -> str:
    source = _HISTORY_STATES.get(value)
    return _t("AlarmStates", source) if source else value


def severity_text(severity: str) -> str:
    source = _SEVERITIES.get(severity)
    return _t("AlarmStates", source) if source else severity


def role_text(role: Role) -> str:
    return _t("Roles", _ROLES[role])


def machine_text(message: Refusal | str | None) -> str:
    """A message or refusal from the machine in the user's language: the reason's template
    translated, then its arguments filled in (a plain text is one of the screens' own)."""
    if message is None or message == "":
        return ""
    if isinstance(message, str):
        return _t(MACHINE_TEXT_CONTEXT, message)
    return message.text(lambda template: _t(MACHINE_TEXT_CONTEXT, template))


def rule_message(error: FieldError) -> str:
    """A broken recipe rule in the user's language: the rule's template translated, then its
    arguments filled in (``%1``, ``%2``...). The error's ``message`` names program fields and
    is for files and the command line, never for the screen."""
    if not error.rule:
        return _t(RULE_TEXT_CONTEXT, GENERIC_RULE_TEXT)
    text = _t(RULE_TEXT_CONTEXT, error.rule)
    for index in range(len(error.args), 0, -1):  # %10 before %1
        text = text.replace(f"%{index}", error.args[index - 1])
    return text


def alarm_title(code: str) -> str:
    """An alarm's title from the catalogue in the user's language (the code itself for a
    code this machine does not raise)."""
    definition = definition_of(code)
    return _t(ALARM_TEXT_CONTEXT, definition.text) if definition is not None else code


def alarm_line(alarm: AlarmView) -> str:
    """An active alarm in one line: its title and what was found, both translated (a
    device's technical words stay in the alarm's details)."""
    title = alarm_title(alarm.code)
    found = machine_text(alarm.detail)
    if not found and alarm.technical:
        found = alarm.source  # the device that reported it (its words are in the details)
    return f"{title}: {found}" if found else title


def history_found(event: AlarmEvent) -> str:
    """What a history row found, in the user's language: its stored message code and
    arguments translated as the active alarms are; a row without them (older rows, a
    device's own words) shows its recorded English detail."""
    detail = refusal_from_json(event.detail_json)
    if detail is not None:
        return machine_text(detail)
    definition = definition_of(event.code)
    if definition is None:
        return event.text
    if event.text.startswith(definition.text):
        return event.text[len(definition.text) :].lstrip(": ")
    return ""


def history_line(event: AlarmEvent) -> str:
    """A history row in one line: the alarm's title and what was found, as ``alarm_line``
    writes an active alarm."""
    found = history_found(event)
    if definition_of(event.code) is None:
        return found
    title = alarm_title(event.code)
    return f"{title}: {found}" if found else title


@dataclass(frozen=True)
class AlarmHelp:
    """What an alarm means, its probable causes and what to do, in the user's language."""

    description: str
    causes: tuple[str, ...]
    remedy: str


def alarm_help(code: str) -> AlarmHelp | None:
    definition = definition_of(code)
    if definition is None:
        return None
    return AlarmHelp(
        _t(ALARM_TEXT_CONTEXT, definition.description),
        tuple(_t(ALARM_TEXT_CONTEXT, cause) for cause in definition.causes),
        _t(ALARM_TEXT_CONTEXT, definition.remedy),
    )


def parameter_text(english: str) -> str:
    """A parameter's description or group title from the data layer's catalogue."""
    return _t(PARAMETER_CONTEXT, english)
