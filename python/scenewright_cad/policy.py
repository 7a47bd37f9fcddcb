"""What generated code may say, checked on its syntax tree before anything runs.

This is the first of the sandbox's layers and the cheapest: it rejects code that imports
a module outside the allow-list, names a dangerous builtin, or reaches for dunder
attributes (the usual way out of a restricted namespace). It is not the wall: code that
gets past it still runs under the operating-system layers in `sandbox.py` (Landlock,
seccomp, rlimits, no capabilities), which do not depend on what the code looks like.
"""

import ast

# Modules generated code may import. Each is imported by the worker before it forks a
# job, so an import in a job never touches the file system.
ALLOWED_MODULES = (
    "cadquery",
    "math",
    "cmath",
    "numpy",
    "typing",
    "itertools",
    "functools",
    "collections",
    "dataclasses",
    "random",
    "copy",
    "enum",
    "fractions",
    "statistics",
)

# Builtins that open files, run code, or walk objects by computed names.
BANNED_NAMES = frozenset(
    {
        "open",
        "eval",
        "exec",
        "compile",
        "__import__",
        "globals",
        "locals",
        "vars",
        "getattr",
        "setattr",
        "delattr",
        "breakpoint",
        "input",
        "help",
        "exit",
        "quit",
        "memoryview",
        "__builtins__",
        "__loader__",
        "__spec__",
    }
)

# Attribute names that lead from an allowed module to the operating system or to
# interpreter internals (cadquery's modules import os and sys themselves).
BANNED_ATTRIBUTES = frozenset(
    {
        "os",
        "sys",
        "subprocess",
        "builtins",
        "importlib",
        "ctypes",
        "socket",
        "shutil",
        "pathlib",
        "io",
        "tempfile",
        "signal",
        "threading",
        "multiprocessing",
        "environ",
        "system",
        "popen",
        "modules",
        "f_globals",
        "f_locals",
        "f_builtins",
        "f_back",
        "f_code",
        "gi_frame",
        "gi_code",
        "cr_frame",
        "cr_code",
        "ag_frame",
        "ag_code",
        "tb_frame",
        "tb_next",
        "co_code",
        "func_globals",
        "mro",
    }
)

# Dunder names generated code may use: defining classes and the usual main guard.
ALLOWED_DUNDERS = frozenset({"__init__", "__name__"})

MAX_CODE_BYTES = 256 * 1024
MAX_NODES = 100_000


class PolicyError(Exception):
    """Code the policy refuses. `kind` is `syntax` or `sandbox`."""

    def __init__(self, kind, message, line=None):
        super().__init__(message)
        self.kind = kind
        self.message = message
        self.line = line


def _top(name):
    return (name or "").split(".")[0]


def check_python(code):
    """Parses `code` and checks it against the policy. Returns the syntax tree."""
    if len(code.encode("utf-8", "replace")) > MAX_CODE_BYTES:
        raise PolicyError("sandbox", f"code is larger than {MAX_CODE_BYTES // 1024} KiB")
    try:
        tree = ast.parse(code, filename="<job>", mode="exec")
    except SyntaxError as e:
        text = (e.text or "").strip()
        where = f": {text}" if text else ""
        raise PolicyError("syntax", f"{e.msg} (line {e.lineno}){where}", e.lineno) from None
    except (ValueError, RecursionError, MemoryError) as e:
        raise PolicyError("syntax", f"unparseable code: {e}") from None
    count = 0
    for node in ast.walk(tree):
        count += 1
        if count > MAX_NODES:
            raise PolicyError("sandbox", f"code has more than {MAX_NODES} syntax nodes")
        line = getattr(node, "lineno", None)
        if isinstance(node, ast.Import):
            for alias in node.names:
                if _top(alias.name) not in ALLOWED_MODULES:
                    raise PolicyError(
                        "sandbox", f"import of '{alias.name}' is not allowed (line {line})", line
                    )
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                raise PolicyError("sandbox", f"relative imports are not allowed (line {line})", line)
            if _top(node.module) not in ALLOWED_MODULES:
                raise PolicyError(
                    "sandbox", f"import from '{node.module}' is not allowed (line {line})", line
                )
            for alias in node.names:
                if alias.name.startswith("__") or alias.name in BANNED_ATTRIBUTES:
                    raise PolicyError(
                        "sandbox",
                        f"importing '{alias.name}' from '{node.module}' is not allowed (line {line})",
                        line,
                    )
        elif isinstance(node, ast.Name):
            if node.id in BANNED_NAMES:
                raise PolicyError("sandbox", f"'{node.id}' is not allowed (line {line})", line)
            if node.id.startswith("__") and node.id not in ALLOWED_DUNDERS:
                raise PolicyError("sandbox", f"name '{node.id}' is not allowed (line {line})", line)
        elif isinstance(node, ast.Attribute):
            attr = node.attr
            if attr in BANNED_ATTRIBUTES:
                raise PolicyError("sandbox", f"attribute '.{attr}' is not allowed (line {line})", line)
            if attr.startswith("__") and attr not in ALLOWED_DUNDERS:
                raise PolicyError("sandbox", f"attribute '.{attr}' is not allowed (line {line})", line)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            if node.name.startswith("__") and node.name not in ALLOWED_DUNDERS:
                raise PolicyError("sandbox", f"defining '{node.name}' is not allowed (line {line})", line)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            for name in node.names:
                if name.startswith("__"):
                    raise PolicyError("sandbox", f"name '{name}' is not allowed (line {line})", line)
    return tree


# OpenSCAD statements that read files.
_SCAD_FILE_STATEMENTS = ("import", "include", "use", "surface")


def check_openscad(code):
    """Rejects OpenSCAD code that reads other files (import, include, use, surface)."""
    if len(code.encode("utf-8", "replace")) > MAX_CODE_BYTES:
        raise PolicyError("sandbox", f"code is larger than {MAX_CODE_BYTES // 1024} KiB")
    stripped = _strip_scad_comments_and_strings(code)
    for lineno, text in enumerate(stripped.splitlines(), start=1):
        for word in _SCAD_FILE_STATEMENTS:
            i = text.find(word)
            while i >= 0:
                before = text[i - 1] if i > 0 else " "
                after = text[i + len(word) :].lstrip()[:1]
                if not (before.isalnum() or before == "_") and after in ("(", "<"):
                    raise PolicyError(
                        "sandbox", f"OpenSCAD '{word}' reads files and is not allowed (line {lineno})", lineno
                    )
                i = text.find(word, i + 1)
    return True


def _strip_scad_comments_and_strings(code):
    out = []
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        if code.startswith("//", i):
            j = code.find("\n", i)
            i = n if j < 0 else j
        elif code.startswith("/*", i):
            j = code.find("*/", i + 2)
            # Keep line numbers: replace the comment by its newlines.
            chunk = code[i : (n if j < 0 else j + 2)]
            out.append("\n" * chunk.count("\n"))
            i = n if j < 0 else j + 2
        elif c == '"':
            j = i + 1
            while j < n and code[j] != '"':
                j += 2 if code[j] == "\\" else 1
            out.append('""')
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)
