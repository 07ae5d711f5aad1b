"""The side profile a recipe asks for, as stored and exchanged.

Why one value with its own module: the kind (line-arc-line, single arc, a curve family, a
drawing), a family's parameters and a drawing's geometry with its file's name and SHA-256 travel
together everywhere a recipe goes (database, history, JSON and CSV files), and are checked
together. A drawn profile keeps the drawing's checked curve itself, not a path to the file:
the recipe cuts the same after the file is gone, and the name and hash say which file it was.

Stored form: the kind's value, and for kinds that need more, one JSON object
``{"params": {...}}`` or ``{"drawing": {...}, "file_name": ..., "file_sha256": ...}``.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

from app.geometry.curved_profile import ProfileSpec
from app.geometry.drawn_profile import DrawnShape, shape_from_dict
from app.geometry.errors import FieldError, GeometryError, format_value, worded
from app.geometry.profile_kinds import ProfileKind, validate_family_parameters
from app.geometry.rule_texts import RuleText

_SHA256 = re.compile(r"^[0-9a-f]{64}$")
KIND_FIELD = "profile_kind"
DATA_FIELD = "profile"


@dataclass(frozen=True)
class RecipeProfile:
    """Kind, family parameters (name, value pairs) and, for a drawn profile, its drawing."""

    kind: ProfileKind = ProfileKind.LINE_ARC_LINE
    params: tuple[tuple[str, float], ...] = ()
    drawing: DrawnShape | None = None
    file_name: str | None = None
    file_sha256: str | None = None

    @property
    def spec(self) -> ProfileSpec:
        """What the geometry needs to solve this profile for a board."""
        return ProfileSpec(self.kind, self.params, self.drawing)

    def validate(self) -> list[FieldError]:
        """Every reason this profile cannot be stored (empty list: valid)."""
        if self.kind.is_family:
            return validate_family_parameters(self.kind, dict(self.params))
        errors: list[FieldError] = []
        if self.params:
            names = ", ".join(name for name, _ in self.params)
            message = f"{DATA_FIELD}: the {self.kind.value} profile has no parameters ({names})"
            error = FieldError(DATA_FIELD, names, "no parameters", message)
            errors.append(worded(error, RuleText.PROFILE_NO_PARAMETERS))
        if self.kind is ProfileKind.DRAWN:
            if self.drawing is None:  # then its file is missing too: one reason is enough
                message = f"{DATA_FIELD}: a drawn profile needs a drawing: import a DXF file"
                error = FieldError(DATA_FIELD, None, "a drawing", message)
                errors.append(worded(error, RuleText.DRAWING_MISSING))
            elif not self.file_name:
                message = f"{DATA_FIELD}: a drawn profile needs its file's name"
                error = FieldError(DATA_FIELD, self.file_name, "a file name", message)
                errors.append(worded(error, RuleText.DRAWING_FILE))
            if self.drawing is not None and not (
                isinstance(self.file_sha256, str) and _SHA256.match(self.file_sha256)
            ):
                allowed = "64 lowercase hexadecimal digits"
                message = (
                    f"{DATA_FIELD}: file_sha256 = {format_value(self.file_sha256)} is not a "
                    f"SHA-256: allowed {allowed}"
                )
                error = FieldError(DATA_FIELD, self.file_sha256, allowed, message)
                errors.append(worded(error, RuleText.DRAWING_FILE))
        elif self.drawing is not None:
            message = f"{DATA_FIELD}: only a drawn profile keeps a drawing, not {self.kind.value}"
            error = FieldError(DATA_FIELD, self.kind.value, "drawn", message)
            errors.append(worded(error, RuleText.PROFILE_NO_DRAWING))
        return errors

    def data(self) -> dict[str, object] | None:
        """The JSON object stored beside the kind (None when the kind needs nothing more)."""
        if self.kind.is_family:
            return {"params": dict(self.params)}
        if self.kind is ProfileKind.DRAWN and self.drawing is not None:
            return {
                "drawing": self.drawing.to_dict(),
                "file_name": self.file_name,
                "file_sha256": self.file_sha256,
            }
        return None

    def data_json(self) -> str | None:
        data = self.data()
        return None if data is None else json.dumps(data, ensure_ascii=False, sort_keys=True)

    def describe(self) -> str:
        """One line for lists and history: the kind, its parameters or its file."""
        if self.kind.is_family and self.params:
            values = ", ".join(f"{name} {format_value(value)}" for name, value in self.params)
            return f"{self.kind.value} ({values})"
        if self.kind is ProfileKind.DRAWN and self.file_name:
            return f"drawn ({self.file_name})"
        return self.kind.value


LINE_ARC_LINE = RecipeProfile()


def _error(message: str, value: object, allowed: str) -> FieldError:
    return FieldError(DATA_FIELD, value, allowed, f"{DATA_FIELD}: {message}")


def parse_recipe_profile(kind_value: object, data_value: object) -> RecipeProfile:
    """The profile from its two stored or exchanged values (kind text; object or JSON text).

    Raises GeometryError naming what is wrong; a blank kind is line-arc-line (older files).
    """
    if kind_value is None or (isinstance(kind_value, str) and not kind_value.strip()):
        kind = ProfileKind.LINE_ARC_LINE
    elif not isinstance(kind_value, str):
        allowed = ", ".join(k.value for k in ProfileKind)
        message = f"{KIND_FIELD} = {format_value(kind_value)} is not a kind: allowed {allowed}"
        raise GeometryError([FieldError(KIND_FIELD, kind_value, allowed, message)])
    else:
        try:
            kind = ProfileKind.parse(kind_value.strip().lower())
        except ValueError as error:
            allowed = ", ".join(k.value for k in ProfileKind)
            raise GeometryError([FieldError(KIND_FIELD, kind_value, allowed, str(error))]) from None
    data = data_value
    if isinstance(data, str):
        if not data.strip():
            data = None
        else:
            try:
                data = json.loads(data)
            except json.JSONDecodeError as error:
                raise GeometryError(
                    [_error(f"is not a JSON object ({error.msg})", data_value, "a JSON object")]
                ) from None
    if data is None:
        data = {}
    if not isinstance(data, Mapping):
        raise GeometryError([_error("must be an object", data_value, "a JSON object")])
    if kind.is_family:
        params = data.get("params", {})
        if not isinstance(params, Mapping):
            raise GeometryError([_error("params must be an object", params, "an object")])
        pairs = []
        for name, value in params.items():
            if isinstance(value, bool) or not isinstance(value, int | float):
                pairs.append((str(name), math.nan))
            else:
                pairs.append((str(name), float(value)))
        profile = RecipeProfile(kind, tuple(sorted(pairs)))
    elif kind is ProfileKind.DRAWN:
        drawing = data.get("drawing")
        shape = None if drawing is None else shape_from_dict(drawing)
        name, digest = data.get("file_name"), data.get("file_sha256")
        profile = RecipeProfile(
            kind,
            drawing=shape,
            file_name=name if isinstance(name, str) else None,
            file_sha256=digest if isinstance(digest, str) else None,
        )
    else:
        profile = RecipeProfile(kind)
    errors = profile.validate()
    if errors:
        raise GeometryError(errors)
    return profile
