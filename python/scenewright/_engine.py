"""The one module that speaks to the engine: the `scenewright` binary.

Everything else in the package reads like Python and calls [`run`][] or [`stream`][].
The binary is found, in order, at:

1. `SCENEWRIGHT_BIN` (a path to the binary or to the checkout's `scenewright` launcher);
2. the checkout this package was installed from (its `scenewright` launcher, which
   builds the binary on first use), recorded at build time or found next to the sources;
3. `scenewright` on `PATH`.

Commands run with `--json`: one JSON document on stdout. Exit code 2 becomes
[`BadInput`][scenewright.errors.BadInput] with the binary's one-line message; exit
code 1 with a document (a scene that failed verification) is returned, not raised.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import signal
import subprocess
import sys
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .errors import BadInput, EngineNotFound, ScenewrightError


def _checkout_root() -> Path | None:
    """The checkout this package belongs to, if any."""
    here = Path(__file__).resolve().parent
    record = here / "_checkout.json"
    candidates: list[Path] = []
    if record.is_file():
        with contextlib.suppress(OSError, ValueError, KeyError, TypeError):
            candidates.append(Path(json.loads(record.read_text(encoding="utf-8"))["root"]))
    # Run from the sources (or an editable install): python/scenewright/ in a checkout.
    candidates.append(here.parent.parent)
    for root in candidates:
        if (root / "scenewright").is_file() and (root / "Cargo.toml").is_file():
            return root
    return None


def command() -> list[str]:
    """The command that runs the binary, or raise `EngineNotFound` saying how to get one."""
    env = os.environ.get("SCENEWRIGHT_BIN")
    if env:
        if not Path(env).is_file():
            raise EngineNotFound(f"SCENEWRIGHT_BIN={env} is not a file")
        return [env]
    root = _checkout_root()
    if root is not None:
        return [str(root / "scenewright")]
    found = shutil.which("scenewright")
    if found:
        return [found]
    raise EngineNotFound(
        "no scenewright binary: set SCENEWRIGHT_BIN to one, put it on PATH, "
        "or install this package from a scenewright checkout"
    )


@dataclass(frozen=True)
class Result:
    """A finished command: its exit code and its JSON document (None when it printed none)."""

    exit_code: int
    document: Any


def _error_line(stderr: str) -> str:
    lines = [ln.strip() for ln in stderr.splitlines() if ln.strip()]
    for ln in reversed(lines):
        if ln.startswith("error:"):
            return ln[len("error:") :].strip()
    return lines[-1] if lines else "no message"


def _finish(args: Sequence[str], code: int, stdout: str, stderr: str) -> Result:
    if code == 2:
        raise BadInput(_error_line(stderr))
    doc: Any = None
    text = stdout.strip()
    if text:
        try:
            doc = json.loads(text)
        except ValueError as e:
            raise ScenewrightError(f"scenewright {args[0]} printed no JSON: {e}", code or 1) from e
    if code != 0 and doc is None:
        raise ScenewrightError(_error_line(stderr), code)
    return Result(code, doc)


def run(args: Sequence[str], timeout: float | None = None) -> Result:
    """Run `scenewright ARGS` and return its exit code and JSON document."""
    cmd = command() + list(args)
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, check=False)
    except subprocess.TimeoutExpired as e:
        raise ScenewrightError(f"scenewright {args[0]} did not finish in {timeout} s") from e
    except OSError as e:
        raise EngineNotFound(f"cannot run {cmd[0]}: {e}") from e
    return _finish(args, p.returncode, p.stdout, p.stderr)


def stream(args: Sequence[str], echo: bool = True) -> Result:
    """Like [`run`][], with the binary's progress lines passed on to our stderr as they come."""
    cmd = command() + list(args)
    try:
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)
    except OSError as e:
        raise EngineNotFound(f"cannot run {cmd[0]}: {e}") from e
    out, err = p.stdout, p.stderr
    if out is None or err is None:  # pragma: no cover - both are pipes
        raise ScenewrightError("cannot read scenewright's output")
    # stdout is read on a thread so that neither pipe can fill while the other is read.
    chunks: list[str] = []
    reader = threading.Thread(target=lambda: chunks.append(out.read()), daemon=True)
    reader.start()
    tail: list[str] = []
    try:
        for line in err:
            if echo:
                sys.stderr.write(line)
            tail = [*tail[-20:], line]
        code = p.wait()
        reader.join()
    except KeyboardInterrupt:
        # The binary stops cleanly on SIGINT too (a dataset keeps what it finished).
        p.send_signal(signal.SIGINT)
        p.wait()
        raise
    return _finish(args, code, "".join(chunks), "".join(tail))
