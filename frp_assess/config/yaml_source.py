"""Reading YAML input safely: bounded work, a line for every key, no silent surprises.

Every file the tool reads as YAML (project and study files) goes through :func:`read_text_file`
and :func:`parse_yaml`, which refuse, with the file, the line and the key where they apply:

* what is not a regular file (a folder, a FIFO, ``/dev/zero``) or is larger than
  :data:`MAX_FILE_BYTES`, before reading it;
* nesting deeper than :data:`MAX_DEPTH` levels, and data that expands to more than
  :data:`MAX_VALUES` values through aliases (the "billion laughs" of 306 bytes);
* control characters (NUL, ESC, DEL, C1 codes, lone surrogates, bidirectional overrides) in
  any text, raw or written as escapes;
* keys that are not names (``1:``, ``~:``, ``yes:``), a key given twice (``<<`` merge keys
  included);
* integers YAML 1.1 reads in another base (``022`` is octal 18, ``0x1f``, ``1:30`` is 90).

Syntax errors are reported alone (nothing after them can be trusted); the other problems of
this level are reported together, in file order.
"""

from __future__ import annotations

import os
import re
import stat
import unicodedata
from pathlib import Path
from typing import Any

import yaml
from yaml.composer import Composer
from yaml.constructor import SafeConstructor
from yaml.resolver import Resolver

try:
    from yaml.cyaml import CParser
except ImportError:  # pragma: no cover - PyYAML without libyaml
    CParser = None

from frp_assess.config.messages import Loc, format_path
from frp_assess.config.problems import MAX_REPORTED, raise_all
from frp_assess.errors import InputError

#: largest YAML input file [bytes] (the largest shipped project file is under 10 kB)
MAX_FILE_BYTES = 2_000_000
#: deepest nesting of lists and mappings (a project file needs 5 levels)
MAX_DEPTH = 50
#: the most digits of a whole number (Python's int() refuses more: sys.get_int_max_str_digits)
MAX_INT_DIGITS = 4300
#: most values (scalars, lists, mappings) once aliases are expanded
MAX_VALUES = 100_000

#: characters refused in any text: C0 controls except tab/newline/CR, DEL, C1 controls, lone
#: surrogates, non-characters and the bidirectional overrides that can disguise text
_BAD_CHARS = (
    "\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\ud800-\udfff\u202a-\u202e\u2066-\u2069\ufffe\uffff"
)
BAD_CHAR_RE = re.compile(f"[{_BAD_CHARS}]")
_SURROGATE_RE = re.compile("[\ud800-\udfff]")


def _join_surrogate_pairs(text: str) -> str:
    """``"\ud83d\ude00"`` (two escapes, as JSON writes one emoji) -> the one character; lone
    surrogates are kept (and then refused as control characters)."""
    return re.sub(
        "[\ud800-\udbff][\udc00-\udfff]",
        lambda m: m.group().encode("utf-16-le", "surrogatepass").decode("utf-16-le"),
        text,
    )


#: an integer as people write it (YAML 1.1 also reads 0o17, 0x1f, 0b101, 017 and 1:30)
_DECIMAL_INT_RE = re.compile(r"^[-+]?(?:0|[1-9][0-9_]*)$")
_OCTAL_RE = re.compile(r"^[-+]?0[0-7_]+$")
_STR_TAG = "tag:yaml.org,2002:str"
_INT_TAG = "tag:yaml.org,2002:int"
_FLOAT_TAG = "tag:yaml.org,2002:float"
_KEY_KINDS = {
    "tag:yaml.org,2002:int": "a number",
    "tag:yaml.org,2002:float": "a number",
    "tag:yaml.org,2002:null": "null (nothing)",
    "tag:yaml.org,2002:bool": "true/false",
    "tag:yaml.org,2002:timestamp": "a date",
}


def describe_char(char: str) -> str:
    """``U+001B (ESCAPE)``: the code point and, if it has one, the Unicode name."""
    name = unicodedata.name(char, "")
    if 0xD800 <= ord(char) <= 0xDFFF:
        name = "a lone UTF-16 surrogate: half of an escaped character"
    if not name:
        name = {"\x00": "NUL", "\x1b": "ESC", "\x7f": "DEL"}.get(char, "control character")
    return f"U+{ord(char):04X} ({name})"


def read_text_file(path: Path, what: str, *, max_bytes: int = MAX_FILE_BYTES) -> str:
    """The UTF-8 text of a regular file of at most ``max_bytes``; InputError otherwise.

    The file is checked (``os.stat``) before it is opened, so that a FIFO or a device is never
    read (reading a FIFO blocks, ``/dev/zero`` never ends).

    Args:
        path: the file.
        what: what the file is, for the messages (``"project file"``).
        max_bytes: the size limit [bytes].
    """
    name = str(path)
    try:
        info = os.stat(path)
    except FileNotFoundError:
        raise InputError(f"no such {what}", file=name) from None
    except NotADirectoryError:
        raise InputError(f"no such {what} (a part of the path is a file)", file=name) from None
    except OSError as exc:
        raise InputError(f"cannot read the {what}: {exc.strerror or exc}", file=name) from None
    if stat.S_ISDIR(info.st_mode):
        raise InputError(f"is a folder, not a {what}", file=name)
    if not stat.S_ISREG(info.st_mode):
        raise InputError(
            f"is not a regular file (a device, pipe or socket); give a {what}", file=name
        )
    if info.st_size > max_bytes:
        raise InputError(_too_large(info.st_size, what, max_bytes), file=name)
    try:
        with open(path, "rb") as handle:
            raw = handle.read(max_bytes + 1)
    except OSError as exc:
        raise InputError(f"cannot read the {what}: {exc.strerror or exc}", file=name) from None
    if len(raw) > max_bytes:  # grew since stat
        raise InputError(_too_large(len(raw), what, max_bytes), file=name)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise InputError(
            f"is not UTF-8 text (byte 0x{raw[exc.start]:02x}); save it with UTF-8 encoding",
            file=name,
            line=line,
        ) from None


def _too_large(size: int, what: str, limit: int) -> str:
    return f"is {size / 1e6:.1f} MB; a {what} is at most {limit / 1e6:g} MB"


class YamlLimitError(yaml.YAMLError):
    """The data exceeds a limit of this module (depth, expanded size)."""

    def __init__(self, message: str, line: int | None) -> None:
        super().__init__(message)
        self.message, self.line = message, line


class ProjectYamlLoader(yaml.SafeLoader):
    """A SafeLoader that bounds the work and records the line of every key and item.

    After :meth:`load`, :attr:`lines` maps each key path -- ``("wall", "height")``,
    ``("interventions", 1)`` -- to its 1-based line, and :attr:`problems` lists the problems
    found in the data (duplicate keys, keys that are not names, integers in another base,
    control characters) as ``(line, key path, message)``.  :func:`parse_yaml` uses the same
    methods on libyaml's parser (:class:`FastProjectYamlLoader`) when it is installed.
    """

    def __init__(self, stream: str) -> None:
        super().__init__(stream)
        self._start()

    def _start(self) -> None:
        self.lines: dict[Loc, int] = {}
        self.problems: list[tuple[int, Loc, str]] = []
        self._depth = 0

    def compose_node(self, parent: yaml.Node | None, index: Any) -> yaml.Node:
        self._depth += 1
        try:
            if self._depth > MAX_DEPTH:
                mark = self.peek_event().start_mark
                raise YamlLimitError(
                    f"nesting deeper than {MAX_DEPTH} levels (lists or mappings inside one "
                    "another); a project file needs 5",
                    mark.line + 1,
                )
            return super().compose_node(parent, index)  # type: ignore[no-any-return]
        finally:
            self._depth -= 1

    def load(self) -> Any:
        """The document's data (``None`` for an empty document)."""
        try:
            node = self.get_single_node()
            if node is None:
                return None
            self._record(node)
            if self.problems:
                return None
            return self.construct_document(node)
        finally:
            self.dispose()

    def _record(self, root: yaml.Node) -> None:
        """Walk the node graph (aliases expanded, iteratively), recording lines and problems."""
        stack: list[tuple[yaml.Node, Loc]] = [(root, ())]
        count = 0
        while stack:
            node, path = stack.pop()
            count += 1
            if len(path) > MAX_DEPTH:  # only through aliases: the composer checks the text
                raise YamlLimitError(
                    f"nesting deeper than {MAX_DEPTH} levels once aliases are expanded (an "
                    "alias '*name' used inside its own block repeats it without end)",
                    node.start_mark.line + 1,
                )
            if count > MAX_VALUES:
                raise YamlLimitError(
                    f"the data expands to more than {MAX_VALUES:,} values (each use of an alias "
                    "'*name' repeats its block); a project file has a few hundred",
                    node.start_mark.line + 1,
                )
            if isinstance(node, yaml.MappingNode):
                first: dict[str, int] = {}
                children: list[tuple[yaml.Node, Loc]] = []
                for key_node, value_node in node.value:
                    line = key_node.start_mark.line + 1
                    key = self._key(key_node, path, line)
                    if key in first:
                        self.problems.append(
                            (
                                line,
                                (*path, key),
                                f"duplicate key {key!r} (first defined on line {first[key]})",
                            )
                        )
                        continue
                    first[key] = line
                    self.lines.setdefault((*path, key), line)
                    children.append((value_node, (*path, key)))
                stack.extend(reversed(children))
            elif isinstance(node, yaml.SequenceNode):
                for i, item in enumerate(node.value):
                    self.lines.setdefault((*path, i), item.start_mark.line + 1)
                stack.extend(reversed([(item, (*path, i)) for i, item in enumerate(node.value)]))
            elif isinstance(node, yaml.ScalarNode):
                self._check_scalar(node, path)

    def _key(self, node: yaml.Node, path: Loc, line: int) -> str:
        if not isinstance(node, yaml.ScalarNode):
            self.problems.append((line, path, "a key must be a name, found a list or mapping"))
            return f"<key on line {line}>"
        key = str(node.value)
        if node.tag != _STR_TAG and key != "<<":
            kind = _KEY_KINDS.get(node.tag, "not text")
            self.problems.append(
                (
                    line,
                    (*path, key),
                    f"the key {key or '(empty)'!r} is read as {kind}, not as a name; keys are "
                    "names such as 'height' (quote it if it must be this text)",
                )
            )
        else:
            self._check_text(key, (*path, key), line)
        return key

    def _check_scalar(self, node: yaml.ScalarNode, path: Loc) -> None:
        line = node.start_mark.line + 1
        text = str(node.value)
        if node.tag == _STR_TAG:
            if _SURROGATE_RE.search(text):  # JSON-style escapes of one character: "\ud83d\ude00"
                text = _join_surrogate_pairs(text)
                node.value = text
            self._check_text(text, path, line)
        elif not node.style and node.tag in (_INT_TAG, _FLOAT_TAG):  # plain: None or ""
            digits = sum(c.isdigit() for c in text)
            if node.tag == _INT_TAG and digits > MAX_INT_DIGITS:  # int() would refuse it
                self.problems.append(
                    (
                        line,
                        path,
                        f"a whole number of {digits} digits; a number here has at most "
                        f"{MAX_INT_DIGITS} digits",
                    )
                )
            elif node.tag == _INT_TAG and not _DECIMAL_INT_RE.match(text):
                if _OCTAL_RE.match(text):
                    value = yaml.safe_load(text)
                    plain = text.lstrip("+-").lstrip("0_") or "0"
                    sign = "-" if text.startswith("-") else ""
                    message = (
                        f"{text} has a leading zero, which YAML reads as the octal number "
                        f"{value}; write {sign}{plain} (or quote it if it is text)"
                    )
                else:
                    message = (
                        f"{text} is a hexadecimal, binary or base-60 number in YAML; write a "
                        "plain decimal number (or quote it if it is text)"
                    )
                self.problems.append((line, path, message))
            elif node.tag == _FLOAT_TAG and ":" in text:
                self.problems.append(
                    (
                        line,
                        path,
                        f"{text} is a base-60 number in YAML; write a plain decimal number "
                        "(or quote it if it is text)",
                    )
                )

    def _check_text(self, text: str, path: Loc, line: int) -> None:
        bad = BAD_CHAR_RE.search(text)
        if bad:
            self.problems.append(
                (line, path, f"control character {describe_char(bad.group())} in the text")
            )


#: the loaders parse_yaml uses, fastest first (libyaml when installed, then pure Python)
LOADERS: list[type[ProjectYamlLoader]] = [ProjectYamlLoader]
if CParser is not None:

    class FastProjectYamlLoader(ProjectYamlLoader, CParser):  # type: ignore[misc, valid-type]
        """:class:`ProjectYamlLoader` on libyaml's parser (scans and parses about 20 times
        faster); PyYAML's own composer still builds the nodes, so the limits apply."""

        def __init__(self, stream: str) -> None:
            CParser.__init__(self, stream)
            Composer.__init__(self)
            SafeConstructor.__init__(self)
            Resolver.__init__(self)
            self._start()

        # the parser's event methods are libyaml's, not the pure-Python Parser's
        check_event = CParser.check_event
        peek_event = CParser.peek_event
        get_event = CParser.get_event
        dispose = CParser.dispose

    LOADERS.insert(0, FastProjectYamlLoader)

# YAML 1.1 (PyYAML) reads 1e-3 as text; accept it as a number, as YAML 1.2 and people do
for _loader in LOADERS:
    _loader.add_implicit_resolver(
        "tag:yaml.org,2002:float",
        re.compile(r"^[-+]?[0-9][0-9_]*(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
        list("-+0123456789"),
    )


def _key_on_line(lines: dict[Loc, int], line: int) -> Loc:
    """The deepest key path that starts on ``line`` (else on the closest line before it)."""
    best: tuple[int, int, Loc] | None = None
    for path, where in lines.items():
        if where <= line:
            rank = (where, len(path), path)
            if best is None or rank[:2] > best[:2]:
                best = rank
    return best[2] if best is not None else ()


def _bad_chars(text: str) -> list[tuple[int, str]]:
    """(line, character) of the first refused character of each line, at most
    :data:`~frp_assess.config.problems.MAX_REPORTED` + 1 lines (linear in the text)."""
    out: list[tuple[int, str]] = []
    line, pos = 1, 0
    for m in BAD_CHAR_RE.finditer(text):
        line += text.count("\n", pos, m.start())
        pos = m.start()
        if not out or out[-1][0] != line:
            out.append((line, m.group()))
            if len(out) > MAX_REPORTED:
                break
    return out


def parse_yaml(text: str, name: str) -> tuple[Any, dict[Loc, int]]:
    """YAML text -> (data, key-path lines); every problem of this level as InputError.

    A syntax error (or a limit exceeded) is raised alone; the other problems together
    (:class:`~frp_assess.config.problems.InputErrors`), in file order.
    """
    if len(text) > MAX_FILE_BYTES:
        raise InputError(
            _too_large(len(text.encode("utf-8")), "YAML text", MAX_FILE_BYTES), file=name
        )
    raw_bad = _bad_chars(text)
    clean = BAD_CHAR_RE.sub("\ufffd", text) if raw_bad else text
    try:
        try:
            loader = LOADERS[0](clean)
            data = loader.load()
        except yaml.MarkedYAMLError:
            if len(LOADERS) == 1:
                raise
            # libyaml refuses some escapes PyYAML reads ("\ud83d\ude00"), and PyYAML's
            # messages are the documented ones: a file with an error is read again by it
            loader = ProjectYamlLoader(clean)
            data = loader.load()
    except YamlLimitError as exc:
        raise InputError(exc.message, file=name, line=exc.line) from None
    except yaml.MarkedYAMLError as exc:
        raise _syntax_error(exc, name, raw_bad, text) from None
    except yaml.YAMLError as exc:
        raise InputError(f"YAML error: {exc}", file=name) from None
    except RecursionError:  # pragma: no cover - MAX_DEPTH stops the composer well before
        raise InputError(f"nesting deeper than {MAX_DEPTH} levels", file=name) from None
    # an alias used several times repeats its problems: one report per line and message
    found = list({(line, msg): (line, path, msg) for line, path, msg in loader.problems}.values())
    for line, char in raw_bad:
        found.append(
            (
                line,
                _key_on_line(loader.lines, line),
                f"control character {describe_char(char)} in the file; remove it",
            )
        )
    found.sort(key=lambda p: p[0])
    raise_all(
        [
            InputError(msg, file=name, line=line, key=format_path(path) or None)
            for line, path, msg in found
        ]
    )
    return data, loader.lines


def _syntax_error(
    exc: yaml.MarkedYAMLError, name: str, raw_bad: list[tuple[int, str]], text: str
) -> InputError:
    mark = exc.problem_mark or exc.context_mark
    line = None if mark is None else mark.line + 1
    if raw_bad:  # the control characters are the likelier cause
        line, char = raw_bad[0]
        return InputError(
            f"control character {describe_char(char)} in the file; remove it", file=name, line=line
        )
    problem = exc.problem or exc.context or "invalid YAML"
    context = ""
    if exc.context and exc.problem:
        where = exc.context_mark
        started = f" started on line {where.line + 1}" if where is not None else ""
        context = f" ({exc.context}{started})"
    lines = text.splitlines()
    here = lines[line - 1] if line is not None and 0 < line <= len(lines) else ""
    indent = here[: len(here) - len(here.lstrip())]
    if "\\t" in problem or "\t" in problem or "\t" in indent:
        context += "; indent with spaces, not tabs"
    return InputError(f"YAML syntax error: {problem}{context}", file=name, line=line)
