"""The ``seismic`` block: the accelerograms (artificial ones or record files) and the block
that joins them to the spectrum.
"""

from __future__ import annotations

from pathlib import PurePath

from pydantic import (
    Field,
    field_validator,
    model_validator,
)

from frp_assess.config.schema.spec_base import (
    MAX_RECORD_DURATION,
    MAX_RECORD_NAME,
    MAX_SEED,
    MAX_TIME_STEP,
    MIN_ARTIFICIAL_DURATION,
    MIN_TIME_STEP,
    T1_RANGE,
    Number,
    RecordFormat,
    RecordUnits,
    WholeNumber,
    _Model,
    located_error,
    unsafe_name_reason,
)
from frp_assess.config.schema.spectrum_spec import (
    Spectrum,
)


# -------------------------------------------------------------------------------- records
class ArtificialRecordsSpec(_Model):
    """Spectrum-compatible artificial accelerograms (SIMQKE), reproducible from the seed."""

    count: WholeNumber = Field(7, ge=1, le=100, description="Number, 1-100 (7).")
    seed: WholeNumber = Field(
        1, ge=0, le=MAX_SEED, description=f"Random seed, 0-{MAX_SEED} (same seed, same set)."
    )
    duration: Number = Field(
        25.0,
        ge=MIN_ARTIFICIAL_DURATION,
        le=MAX_RECORD_DURATION,
        description=f"Total duration [s], {MIN_ARTIFICIAL_DURATION:g}-{MAX_RECORD_DURATION:g} "
        "(25, NTC minimum).",
    )
    dt: Number = Field(
        0.005,
        ge=MIN_TIME_STEP,
        le=MAX_TIME_STEP,
        description=f"Time step [s], {MIN_TIME_STEP:g}-{MAX_TIME_STEP:g} (0.005).",
    )


class RecordFileSpec(_Model):
    """A recorded accelerogram file."""

    path: str = Field(description="File path, relative to the project file.")
    format: RecordFormat = Field(
        "auto", description="auto | at2 (PEER NGA) | esm (ESM/ITACA) | two-column | one-column."
    )
    units: RecordUnits = Field("g", description="Units of the samples: g | m/s2 | cm/s2 | gal.")
    dt: Number | None = Field(
        None,
        ge=MIN_TIME_STEP,
        le=MAX_TIME_STEP,
        description=f"Time step [s], {MIN_TIME_STEP:g}-{MAX_TIME_STEP:g}, required for "
        "one-column files.",
    )
    name: str | None = Field(
        None,
        description="Name in the results and of the exported records/<name>.AT2 (default: the "
        f"file name without extension); unique, at most {MAX_RECORD_NAME} characters, no path "
        "separators, not starting with a dot.",
    )

    @property
    def record_name(self) -> str:
        """The record's name: ``name``, else the file name without its extension."""
        return self.name if self.name is not None else PurePath(self.path).stem

    @field_validator("name")
    @classmethod
    def _safe_name(cls, value: str | None) -> str | None:
        if value is not None and (reason := unsafe_name_reason(value)) is not None:
            raise located_error(
                f"record name {value!r} is not a safe file name: {reason}; the results export "
                "it as records/<name>.AT2"
            )
        return value

    @model_validator(mode="after")
    def _dt_for_one_column(self) -> RecordFileSpec:
        if self.format == "one-column" and self.dt is None:
            raise located_error("a one-column file needs 'dt' [s]; none was found", "dt")
        return self


class RecordsSpec(_Model):
    """The accelerograms: artificial ones or files (exactly one of the two)."""

    artificial: ArtificialRecordsSpec | None = Field(
        None, description="Generate artificial records compatible with the spectrum."
    )
    files: list[RecordFileSpec] | None = Field(
        None, min_length=1, description="Recorded accelerograms, read from files."
    )
    scale_to_spectrum: bool = Field(
        True, description="Scale every record file to the spectrum's a_g*S (true)."
    )

    @model_validator(mode="after")
    def _exactly_one(self) -> RecordsSpec:
        if self.artificial is not None and self.files is not None:
            raise located_error("give either 'artificial' or 'files', not both", "files")
        if self.artificial is None and self.files is None:
            raise located_error("give either 'artificial' or 'files'; neither was found")
        return self

    @model_validator(mode="after")
    def _unique_names(self) -> RecordsSpec:
        first: dict[str, int] = {}
        for i, f in enumerate(self.files or []):
            name = f.record_name
            key = "name" if f.name is not None else "path"
            if f.name is None and (reason := unsafe_name_reason(name)) is not None:
                raise located_error(
                    f"the file name {name!r} is not a safe record name: {reason}; give a 'name:'",
                    "files",
                    i,
                    key,
                )
            j = first.setdefault(name.casefold(), i)
            if j != i:
                raise located_error(
                    f"record name {name!r} is already the name of files[{j}]; each record needs "
                    "its own name (give a 'name:')",
                    "files",
                    i,
                    key,
                )
        return self


def _default_records() -> RecordsSpec:
    return RecordsSpec(artificial=ArtificialRecordsSpec())


class SeismicSpec(_Model):
    """The site's seismic action: a spectrum and the records compatible with it."""

    spectrum: Spectrum = Field(
        description="Elastic spectrum at 5 % damping: type ntc2018 | ec8 | preset | table."
    )
    records: RecordsSpec = Field(
        default_factory=_default_records,
        description="Accelerograms (default: 7 artificial, seed 1, 25 s, dt 0.005 s).",
    )
    t1: Number = Field(
        1.0,
        ge=T1_RANGE[0],
        le=T1_RANGE[1],
        description="Reference period T1 [s] of the compatibility checks, 0.05-10.",
    )
