"""Alarm titles in English and Slovenian for the woodworking events.

Why from the Qt translation file: the screens already translate every alarm title through
``resources/translations/stave_sl.ts`` (a test keeps it complete); the plant connection reads
the same file, without Qt, so a title is translated once for both.
"""

from __future__ import annotations

import functools
import xml.etree.ElementTree as ET

from app.machine.alarms import definition_of
from app.resources import resource_path

ALARM_CONTEXT = "AlarmText"  # the context the screens use for alarm titles
LOCALES = ("en", "sl")


@functools.cache
def _slovenian() -> dict[str, str]:
    path = resource_path("translations", "stave_sl.ts")
    texts: dict[str, str] = {}
    for context in ET.parse(path).getroot().iter("context"):
        if context.findtext("name") != ALARM_CONTEXT:
            continue
        for message in context.iter("message"):
            source = message.findtext("source")
            translation = message.findtext("translation")
            if source and translation:
                texts[source] = translation
    return texts


def alarm_titles(code: str) -> dict[str, str]:
    """Locale -> title of alarm ``code`` (English if a translation is missing)."""
    definition = definition_of(code)
    english = definition.text if definition is not None else code
    return {"en": english, "sl": _slovenian().get(english, english)}
