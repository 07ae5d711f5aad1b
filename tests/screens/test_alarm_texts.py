"""Alarms that help: every alarm code has its title, description, causes and remedy in both
languages, and no message the machine puts on screen carries a program identifier."""

from __future__ import annotations

import math
import re
from dataclasses import replace
from datetime import UTC, datetime, timedelta

import pytest

from app.data.recipe import BarrelType
from app.data.recipe_profile import RecipeProfile
from app.data.records import AlarmEvent, AlarmState
from app.geometry.profile_kinds import ProfileKind
from app.geometry.ratio import Ratio
from app.geometry.rule_texts import RuleText
from app.machine.alarms import CATALOGUE, AlarmCode
from app.machine.planner.jog import Jogger
from app.machine.refusals import Reason
from app.resources import resource_path
from app.screens.alarm_detail import episode
from app.screens.catalogue_text import alarm_texts
from app.screens.texts import (
    ALARM_TEXT_CONTEXT,
    GENERIC_RULE_TEXT,
    RULE_TEXT_CONTEXT,
    rule_message,
)
from tests.data.test_recipe import make_recipe
from tests.screens.test_translations import messages

SNAKE_CASE = re.compile(r"\b[A-Za-z][A-Za-z0-9]*_[A-Za-z0-9_]+\b")
TS = {language: resource_path("translations", f"stave_{language}.ts") for language in ("en", "sl")}


@pytest.mark.parametrize("code", list(AlarmCode))
def test_every_alarm_code_has_all_its_texts_in_both_languages(code: AlarmCode) -> None:
    definition = CATALOGUE[code]
    assert definition.code is code
    assert definition.text and definition.description and definition.remedy
    assert definition.causes and all(definition.causes)
    for language, path in TS.items():
        found = messages(path)
        for text in alarm_texts(definition):
            message = found.get((ALARM_TEXT_CONTEXT, text))
            assert message is not None, f"{language}: {code} {text!r} not in the source"
            translation = message.find("translation")
            assert translation is not None and translation.get("type") is None, (language, text)
            assert (translation.text or "").strip(), (language, text)


def test_no_alarm_or_refusal_template_contains_a_program_identifier() -> None:
    texts = [(f"{d.code} text", t) for d in CATALOGUE.values() for t in alarm_texts(d)]
    texts += [(f"Reason.{r.name}", r.value) for r in Reason]
    assert [(where, text) for where, text in texts if SNAKE_CASE.search(text)] == []


def test_the_recipe_rules_words_are_translated_and_name_no_program_identifier() -> None:
    templates = [rule.value for rule in RuleText] + [GENERIC_RULE_TEXT]
    assert [text for text in templates if SNAKE_CASE.search(text)] == []
    for language, path in TS.items():
        found = messages(path)
        for text in templates:
            message = found.get((RULE_TEXT_CONTEXT, text))
            assert message is not None, f"{language}: {text!r} not in the source"
            translation = message.find("translation")
            assert translation is not None and translation.get("type") is None, (language, text)


BROKEN_RECIPES: list[dict[str, object]] = [
    {"name": ""},
    {"name": " padded"},
    {"name": "line\nbreak"},
    {"name": 5},
    {"note": "n" * 501},
    {"length_mm": 100.0},
    {"length_mm": math.nan},
    {"thickness_mm": 200.0},
    {"tilt_deg": 80.0},
    {"tilt_deg": 0.1},
    {"length_ratio": Ratio(1, 2)},
    {"width_ratio": Ratio(1, 1)},
    {"width_ratio": Ratio(1, 10)},
    {"barrel_type": "square"},
    {"barrel_type": BarrelType.ROUND},
    {"barrel_type": BarrelType.ROUND, "barrel_diameter_mm": 100.0},
    {"barrel_type": BarrelType.OVAL, "barrel_diameter_mm": 700.0},
    {
        "barrel_type": BarrelType.OVAL,
        "barrel_diameter_mm": 700.0,
        "barrel_minor_diameter_mm": 900.0,
    },
    {"barrel_minor_diameter_mm": 500.0},
    {"barrel_perimeter_mm": 10.0},
    {"target_width_mm": 70.0},
    {"target_width_mm": 500.0},
    {"profile": RecipeProfile(ProfileKind.DRAWN)},
    {"profile": RecipeProfile(ProfileKind.PARABOLA, (("exponent", 99.0),))},
    {"profile": RecipeProfile(ProfileKind.SUPERELLIPSE, (("exponent", 99.0),))},
    {"profile": RecipeProfile(ProfileKind.SINGLE_ARC, (("exponent", 2.0),))},
]


@pytest.mark.parametrize("changes", BROKEN_RECIPES)
def test_recipe_validation_on_screen_names_no_program_identifier(qapp, changes) -> None:
    """Every error of a broken recipe has its words (a template with arguments), and what
    the screen shows contains no program identifier (it said "width_ratio = 1 ...")."""
    errors = replace(make_recipe(), **changes).validate()
    assert errors, changes
    for error in errors:
        assert error.rule, error.message  # every recipe check has its words
        shown = rule_message(error)
        assert not SNAKE_CASE.search(shown), shown
        assert "%" not in shown, shown  # every argument filled in


def test_the_soft_limit_refusals_name_no_program_identifier() -> None:
    """The jog's refusals at and beyond each soft limit (they used to name ``min_position``)."""
    texts: list[str] = []
    for position, direction in ((0.0, -1), (500.0, 1), (-3.0, -1), (503.0, 1)):
        jog = Jogger("X", position, 0.0, 500.0, 100.0, 500.0, 20000.0, max_acceleration=2000.0)
        texts.append(str(jog.press(direction).reason))
        texts.append(str(jog.step(10.0 * direction).reason))
    near = Jogger("X", 495.0, 0.0, 500.0, 100.0, 500.0, 20000.0, max_acceleration=2000.0)
    texts.append(str(near.step(10.0).reason))
    assert all("soft limit" in text for text in texts), texts
    assert [text for text in texts if SNAKE_CASE.search(text)] == []


def _event(minute: int, before: AlarmState, after: AlarmState, user: str = "") -> AlarmEvent:
    moment = datetime(2026, 3, 1, 8, 0, tzinfo=UTC) + timedelta(minutes=minute)
    return AlarmEvent(moment, "E010", "Drive fault", "X", before, after, user or None)


def test_the_detail_shows_one_occurrence_of_the_alarm() -> None:
    n, on, acked, rtn = (
        AlarmState.NORMAL,
        AlarmState.ACTIVE_UNACKED,
        AlarmState.ACTIVE_ACKED,
        AlarmState.RETURNED_UNACKED,
    )
    first = [_event(0, n, on), _event(1, on, rtn), _event(2, rtn, n, "anna")]
    second = [_event(10, n, on), _event(11, on, acked, "ben"), _event(12, acked, n)]
    events = list(reversed(first + second))  # the database gives the newest first
    at = datetime(2026, 3, 1, 8, 10, tzinfo=UTC)
    assert episode(events, at) == second
    assert episode(events, at - timedelta(minutes=9)) == first
    still_on = [*first, _event(10, n, on)]
    assert episode(still_on, at + timedelta(minutes=5)) == [still_on[-1]]
