"""The exceptions the package raises."""

from __future__ import annotations


class ScenewrightError(Exception):
    """A scenewright command failed; `exit_code` is the binary's (1 internal, 2 bad input)."""

    def __init__(self, message: str, exit_code: int = 1) -> None:
        super().__init__(message)
        self.message = message
        self.exit_code = exit_code


class BadInput(ScenewrightError):
    """The prompt, an option or a path was unusable (the binary's exit code 2)."""

    def __init__(self, message: str) -> None:
        super().__init__(message, 2)


class EngineNotFound(ScenewrightError):
    """No `scenewright` binary could be found (see `scenewright._engine.command`)."""

    def __init__(self, message: str) -> None:
        super().__init__(message, 1)
