"""The long-lived CAD worker: imports CadQuery once, then runs each job in a fresh,
confined process forked from this warm image.

Protocol: one JSON object per line. The worker writes `{"type": "ready", ...}` once it
is warm, then answers every job line on stdin with one result line on stdout:

  job    {"id": "j1", "language": "cadquery"|"openscad", "code": "...",
          "timeout_s": 10, "memory_mb": 2048, "max_output_mb": 64,
          "max_triangles": 200000, "check_policy": true}
  result {"id": "j1", "ok": true, "stl": "<path>", "triangles": n, "volume": v,
          "bbox": [[x0, y0, z0], [x1, y1, z1]], "valid": true, "ms": {...},
          "output": "what the code printed (first 4 KiB)"}
      or {"id": "j1", "ok": false, "error": {"kind": k, "message": m, "line": n},
          "ms": {...}, "output": "..."}

Error kinds: syntax, runtime, invalid_solid, no_result, timeout, sandbox, memory,
output_limit, crash. The job process is discarded after every job; the worker itself
never runs generated code. Units are whatever the code uses (scenewright asks for mm).
"""

import json
import os
import select
import shutil
import signal
import sys
import time
import traceback

from . import policy, sandbox

OUTPUT_PREVIEW = 4096
RESULT_JSON_MAX = 1 << 20
VIOLATIONS_MAX = 64 * 1024


class Worker:
    def __init__(self, root, strict):
        self.root = root
        self.strict = strict
        self.seq = 0
        self.previous_job = None
        self.cadquery = None
        self.openscad = shutil.which("openscad", path="/usr/bin:/usr/local/bin:/bin")
        self.read_paths = []
        self.caps = sandbox.probe()
        self.selftest = {}
        self.standby = None
        self.standby_limits = _default_limits()

    # --- start-up ------------------------------------------------------------------

    def warm(self):
        # Everything generated code may import is imported here, once, so that a job
        # never needs to read a module from disk.
        import importlib

        for name in policy.ALLOWED_MODULES:
            try:
                importlib.import_module(name)
            except ImportError:
                pass
        try:
            import cadquery as cq

            self.cadquery = cq
            from OCP.BRepMesh import BRepMesh_IncrementalMesh  # noqa: F401
            from OCP.StlAPI import StlAPI_Writer  # noqa: F401

            # Touch the kernel once (solids, fillets, extrusions, meshing) without
            # booleans: OCCT's boolean operations start a thread pool, and a fork of a
            # threaded process can deadlock. The worker must stay single-threaded.
            part = cq.Workplane("XY").box(10, 10, 10).edges("|Z").fillet(1)
            _mesh(part.val().wrapped, 0.01, 0.1)
            part = cq.Workplane("XY").circle(5).extrude(3)
            _mesh(part.val().wrapped, 0.01, 0.1)
        except ImportError:
            self.cadquery = None
        prefixes = {sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix}
        self.read_paths = sorted(p for p in prefixes if p) + [
            "/usr/lib",
            "/usr/lib64",
            "/lib",
            "/lib64",
            "/usr/share",
            "/etc/ld.so.cache",
            "/etc/fonts",
            "/etc/localtime",
            "/dev/urandom",
            "/dev/null",
        ]

    def threads(self):
        try:
            return len(os.listdir("/proc/self/task"))
        except OSError:
            return 1

    def run_selftest(self):
        """Forks two confined processes that try to leave: one reads a file outside its
        directory (must be refused), one opens a socket (must be killed)."""
        results = {}
        probe_dir = self._new_job_dir("selftest")
        for name, action in (("file", _selftest_read), ("network", _selftest_socket)):
            pid = os.fork()
            if pid == 0:
                code = 1
                try:
                    self._confine(probe_dir, allow_exec=False, limits=_default_limits())
                    code = action()
                finally:
                    os._exit(code)
            _, status = os.waitpid(pid, 0)
            if name == "file":
                results[name] = os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0
            else:
                results[name] = os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGSYS
        shutil.rmtree(probe_dir, ignore_errors=True)
        self.selftest = results
        return all(results.values())

    def ready_message(self):
        languages = []
        if self.cadquery is not None:
            languages.append("cadquery")
        if self.openscad:
            languages.append("openscad")
        return {
            "type": "ready",
            "pid": os.getpid(),
            "python": sys.version.split()[0],
            "cadquery": getattr(self.cadquery, "__version__", None),
            "openscad": self.openscad,
            "languages": languages,
            "sandbox": dict(self.caps, selftest=self.selftest, threads_at_fork=self.threads()),
        }

    # --- jobs ------------------------------------------------------------------------

    def _new_job_dir(self, tag):
        self.seq += 1
        path = os.path.join(self.root, f"{tag}-{self.seq}")
        os.mkdir(path, 0o700)
        return path

    def _confine(self, job_dir, allow_exec, limits):
        exec_paths = []
        if allow_exec and self.openscad:
            exec_paths = [self.openscad, "/usr/lib", "/usr/lib64", "/lib", "/lib64"]
        sandbox.confine(
            job_dir,
            self.read_paths,
            limits,
            self.caps["landlock_abi"],
            exec_paths=exec_paths,
            allow_exec=allow_exec,
        )

    def handle(self, req):
        started = time.monotonic()
        jid = str(req.get("id", ""))
        language = req.get("language", "cadquery")
        code = req.get("code")
        if not isinstance(code, str):
            return _error(jid, "syntax", "the job has no code", started)
        limits = _limits_of(req)
        if language == "cadquery":
            if self.cadquery is None:
                return _error(jid, "crash", "CadQuery is not installed in this worker", started)
            check = policy.check_python
        elif language == "openscad":
            if not self.openscad:
                return _error(jid, "crash", "OpenSCAD is not installed on this machine", started)
            check = policy.check_openscad
        else:
            return _error(jid, "syntax", f"unknown language '{language}'", started)
        try:
            if req.get("check_policy", True):
                check(code)
            elif len(code) > policy.MAX_CODE_BYTES:
                raise policy.PolicyError("sandbox", "code is too large")
            elif language == "cadquery":
                compile(code, "<job>", "exec")
        except policy.PolicyError as e:
            return _error(jid, e.kind, e.message, started, line=e.line)
        except SyntaxError as e:
            return _error(jid, "syntax", f"{e.msg} (line {e.lineno})", started, line=e.lineno)
        if self.previous_job:
            shutil.rmtree(self.previous_job, ignore_errors=True)
            self.previous_job = None
        forked = time.monotonic()
        standby = self.standby
        self.standby = None
        in_process_layers = bool(req.get("check_policy", True))
        if standby is not None and language == "cadquery" and limits == self.standby_limits and in_process_layers:
            pid, job_dir, vr, code_w = standby
            try:
                _send_job(code_w, code, req)
            except OSError:
                pass  # the standby died: its status below says how
        else:
            if standby is not None:
                self._discard(standby)
            job_dir = self._new_job_dir("job")
            if language == "openscad":
                with open(os.path.join(job_dir, "part.scad"), "w") as f:
                    f.write(code)
            vr, vw = os.pipe()
            sys.stdout.flush()
            sys.stderr.flush()
            pid = os.fork()
            if pid == 0:
                os.close(vr)
                if language == "openscad":
                    _openscad_child(self, job_dir, limits, vw)
                else:
                    _cadquery_child(self, job_dir, code, limits, vw, req)
                os._exit(3)  # not reached
            os.close(vw)
        self.previous_job = job_dir
        status, timed_out, rusage = _wait(pid, limits["timeout_s"])
        violations = _read_all(vr, VIOLATIONS_MAX).decode("utf-8", "replace").strip()
        os.close(vr)
        ms = {"total": _ms(started), "job": _ms(forked)}
        output = _read_text(os.path.join(job_dir, "output.txt"), OUTPUT_PREVIEW)
        result = _read_json(os.path.join(job_dir, "result.json"))
        peak_mb = round(rusage.ru_maxrss / 1024, 1) if rusage else None
        base = {"id": jid, "ms": ms, "output": output, "pid": pid, "peak_rss_mb": peak_mb}
        if timed_out:
            return dict(base, ok=False, error={"kind": "timeout", "message": f"the job ran longer than {limits['timeout_s']:g} s and was killed"})
        if violations:
            first = violations.splitlines()[0]
            return dict(base, ok=False, error={"kind": "sandbox", "message": first, "all": violations.splitlines()[:20]})
        if os.WIFSIGNALED(status):
            sig = os.WTERMSIG(status)
            if sig == signal.SIGSYS:
                msg = "the sandbox killed the job: a forbidden system call (network, process creation, program execution or a kernel interface)"
                return dict(base, ok=False, error={"kind": "sandbox", "message": msg})
            if sig in (signal.SIGXCPU,) or (sig == signal.SIGKILL and rusage and _cpu_s(rusage) >= limits["cpu_s"] - 0.05):
                return dict(base, ok=False, error={"kind": "timeout", "message": f"the job used more than {limits['cpu_s']:g} s of CPU time and was killed"})
            if sig == signal.SIGXFSZ:
                return dict(base, ok=False, error={"kind": "output_limit", "message": f"the job wrote a file larger than {limits['max_file_bytes'] >> 20} MiB and was killed"})
            name = signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else str(sig)
            if result is None:
                return dict(base, ok=False, error={"kind": "crash", "message": f"the job process died ({name})"})
        if result is None:
            if language == "openscad":
                return dict(base, **_openscad_result(job_dir, status, output, limits))
            code_ = os.WEXITSTATUS(status) if os.WIFEXITED(status) else -1
            return dict(base, ok=False, error={"kind": "crash", "message": f"the job process exited ({code_}) without a result"})
        if result.get("ok"):
            stl = os.path.join(job_dir, "result.stl")
            checked = _check_stl(stl, limits)
            if checked is not None:
                return dict(base, ok=False, error=checked)
            result["stl"] = stl
        inner_ms = result.get("ms") if isinstance(result.get("ms"), dict) else {}
        result.update(base)
        result["ms"] = dict(inner_ms, **ms)
        return result

    def prefork(self):
        """Forks and confines the next CadQuery job's process ahead of time, so a job
        pays neither the fork of the large warm image nor the sandbox set-up."""
        if self.standby is not None or self.cadquery is None:
            return
        job_dir = self._new_job_dir("job")
        vr, vw = os.pipe()
        code_r, code_w = os.pipe()
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:
            os.close(vr)
            os.close(code_w)
            _cadquery_child(self, job_dir, None, self.standby_limits, vw, None, code_r=code_r)
            os._exit(3)  # not reached
        os.close(vw)
        os.close(code_r)
        self.standby = (pid, job_dir, vr, code_w)

    def _discard(self, standby):
        pid, job_dir, vr, code_w = standby
        for fd in (vr, code_w):
            try:
                os.close(fd)
            except OSError:
                pass
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        os.waitpid(pid, 0)
        shutil.rmtree(job_dir, ignore_errors=True)

    def close(self):
        if self.standby is not None:
            self._discard(self.standby)
            self.standby = None
        if self.previous_job:
            shutil.rmtree(self.previous_job, ignore_errors=True)


# --- the job process -------------------------------------------------------------------


def _child_fds(job_dir, keep):
    """Points stdin at /dev/null and stdout and stderr at the job's output file, and
    closes every other descriptor except `keep` (the worker's protocol pipes above all)."""
    os.chdir(job_dir)
    out = os.open("output.txt", os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW, 0o600)
    null = os.open("/dev/null", os.O_RDONLY)
    os.dup2(null, 0)
    os.dup2(out, 1)
    os.dup2(out, 2)
    for fd in (out, null):
        if fd > 2 and fd not in keep:
            os.close(fd)
    low = 3
    for fd in sorted(keep):
        os.closerange(low, fd)
        low = fd + 1
    os.closerange(low, 1 << 16)
    os.environ.clear()
    os.environ.update({"HOME": job_dir, "TMPDIR": job_dir, "PATH": "/usr/bin:/bin", "LANG": "C.UTF-8", "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"})


def _write_result(obj):
    data = json.dumps(obj).encode()
    fd = os.open("result.json", os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW, 0o600)
    try:
        os.write(fd, data)
    finally:
        os.close(fd)


def _receive_job(fd):
    chunks = []
    total = 0
    while True:
        b = os.read(fd, 65536)
        if not b:
            break
        total += len(b)
        if total > policy.MAX_CODE_BYTES * 2 + 65536:
            raise ValueError("job too large")
        chunks.append(b)
    os.close(fd)
    msg = json.loads(b"".join(chunks))
    return msg["code"], msg["req"]


def _cadquery_child(worker, job_dir, code, limits, vw, req, code_r=None):
    try:
        _child_fds(job_dir, (vw,) if code_r is None else (vw, code_r))
        worker._confine(job_dir, allow_exec=False, limits=limits)
        # The audit hook and the restricted builtins are the in-process layers; a job
        # with check_policy false (tests of the operating-system layers) runs without.
        if code_r is not None or req.get("check_policy", True):
            _install_audit_hook(job_dir, worker.read_paths, vw)
        if code_r is not None:
            # A standby process: confined before the job existed; now wait for it.
            code, req = _receive_job(code_r)
    except BaseException as e:  # the sandbox could not be set up: run nothing
        try:
            os.write(vw, f"sandbox set-up failed: {e}\n".encode())
        finally:
            os._exit(4)
    try:
        result = _run_cadquery(worker.cadquery, code, limits, req)
    except MemoryError:
        result = {"ok": False, "error": {"kind": "memory", "message": f"the job needed more than {limits['memory_bytes'] >> 20} MiB of memory"}}
    except BaseException as e:  # noqa: BLE001 - everything the code raised is a result
        result = {"ok": False, "error": _runtime_error(e)}
    try:
        _write_result(result)
    except BaseException:
        os._exit(5)
    sys.stdout.flush()
    os._exit(0)


def _runtime_error(e):
    line = None
    tb = e.__traceback__
    while tb is not None:
        if tb.tb_frame.f_code.co_filename == "<job>":
            line = tb.tb_lineno
        tb = tb.tb_next
    name = type(e).__name__
    message = f"{name}: {e}" if str(e) else name
    if line is not None:
        message += f" (line {line})"
    kind = "memory" if isinstance(e, MemoryError) else "runtime"
    if isinstance(e, PermissionError):
        kind = "sandbox"
    if isinstance(e, OSError) and e.errno == 27:  # EFBIG: the file-size limit
        kind = "output_limit"
        message = f"the job wrote more than its output limit: {message}"
    if isinstance(e, SyntaxError):
        kind = "syntax"
    return {"kind": kind, "message": message[:2000], "line": line}


def _run_cadquery(cq, code, limits, req):
    import builtins

    shown = []

    def show_object(obj, *args, **kwargs):
        shown.append(obj)

    def _restricted_import(name, globals=None, locals=None, fromlist=(), level=0):
        if level != 0 or name.split(".")[0] not in policy.ALLOWED_MODULES:
            raise ImportError(f"import of '{name}' is not allowed")
        return builtins.__import__(name, globals, locals, fromlist, level)

    safe = {k: getattr(builtins, k) for k in _SAFE_BUILTINS if hasattr(builtins, k)}
    safe["__import__"] = _restricted_import
    if not req.get("check_policy", True):
        safe = builtins.__dict__
    g = {"__name__": "__sw_job__", "__builtins__": safe, "cq": cq, "cadquery": cq, "show_object": show_object, "debug": _noop, "log": _noop}
    t0 = time.monotonic()
    exec(compile(code, "<job>", "exec"), g)
    t_exec = _ms(t0)
    obj = shown[-1] if shown else None
    if obj is None:
        for key in ("result", "part", "model", "shape", "solid", "obj", "body", "assembly"):
            if key in g and g[key] is not None:
                obj = g[key]
                break
    if obj is None:
        candidates = [v for k, v in g.items() if not k.startswith("_") and _is_cad(cq, v)]
        obj = candidates[-1] if candidates else None
    if obj is None:
        return {"ok": False, "error": {"kind": "no_result", "message": "the code made no shape: assign it to `result` (or call show_object(result))"}}
    shape, problem = _to_shape(cq, obj)
    if shape is None:
        return {"ok": False, "error": {"kind": "invalid_solid", "message": problem}}
    solids = shape.Solids()
    if not solids:
        kind = type(shape).__name__
        return {"ok": False, "error": {"kind": "invalid_solid", "message": f"the result is a {kind} with no solid in it"}}
    valid = bool(shape.isValid())
    volume = float(shape.Volume())
    bb = shape.BoundingBox()
    bbox = [[bb.xmin, bb.ymin, bb.zmin], [bb.xmax, bb.ymax, bb.zmax]]
    if not valid:
        return {"ok": False, "error": {"kind": "invalid_solid", "message": "OCCT's shape check failed: the solid is not valid (self-intersecting or open)"}, "volume": volume, "bbox": bbox}
    if not volume > 0:
        return {"ok": False, "error": {"kind": "invalid_solid", "message": f"the solid has no volume ({volume:g})"}, "volume": volume, "bbox": bbox}
    diag = max(1e-9, sum((bbox[1][i] - bbox[0][i]) ** 2 for i in range(3)) ** 0.5)
    linear = min(max(diag * float(req.get("linear_deflection", 2e-4)), 1e-4), diag * 0.01)
    angular = float(req.get("angular_deflection", 0.1))
    t1 = time.monotonic()
    triangles = _mesh(shape.wrapped, linear, angular, count_only=True)
    if triangles > limits["max_triangles"]:
        return {"ok": False, "error": {"kind": "output_limit", "message": f"the mesh has {triangles} triangles (more than {limits['max_triangles']})"}}
    _write_stl(shape.wrapped, "result.stl")
    return {
        "ok": True,
        "triangles": triangles,
        "volume": volume,
        "bbox": bbox,
        "solids": len(solids),
        "valid": valid,
        "deflection": [linear, angular],
        "ms": {"exec": t_exec, "export": _ms(t1)},
    }


def _is_cad(cq, v):
    return isinstance(v, (cq.Workplane, cq.Shape, cq.Assembly))


def _to_shape(cq, obj):
    if isinstance(obj, (list, tuple)):
        parts = []
        for o in obj:
            s, problem = _to_shape(cq, o)
            if s is None:
                return None, problem
            parts.append(s)
        if not parts:
            return None, "the result is an empty list"
        return (parts[0] if len(parts) == 1 else cq.Compound.makeCompound(parts)), None
    if isinstance(obj, cq.Assembly):
        return obj.toCompound(), None
    if isinstance(obj, cq.Workplane):
        vals = [v for v in obj.vals() if isinstance(v, cq.Shape)]
        if not vals:
            return None, "the Workplane holds no shape (only points, wires or nothing)"
        return (vals[0] if len(vals) == 1 else cq.Compound.makeCompound(vals)), None
    if isinstance(obj, cq.Shape):
        return obj, None
    return None, f"the result is a {type(obj).__name__}, not a CadQuery shape"


def _mesh(wrapped, linear, angular, count_only=False):
    from OCP.BRep import BRep_Tool
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS

    m = BRepMesh_IncrementalMesh(wrapped, linear, False, angular, False)
    m.Perform()
    if not count_only:
        return 0
    n = 0
    exp = TopExp_Explorer(wrapped, TopAbs_FACE)
    while exp.More():
        tri = BRep_Tool.Triangulation_s(TopoDS.Face_s(exp.Current()), TopLoc_Location())
        if tri is not None:
            n += tri.NbTriangles()
        exp.Next()
    return n


def _write_stl(wrapped, path):
    from OCP.StlAPI import StlAPI_Writer

    w = StlAPI_Writer()
    w.ASCIIMode = False
    if not w.Write(wrapped, path):
        raise RuntimeError("writing the STL failed")


def _noop(*args, **kwargs):
    return None


_SAFE_BUILTINS = (
    "abs", "all", "any", "ascii", "bin", "bool", "bytes", "callable", "chr", "complex",
    "dict", "divmod", "enumerate", "filter", "float", "format", "frozenset", "hash", "hex",
    "int", "isinstance", "issubclass", "iter", "len", "list", "map", "max", "min", "next",
    "object", "oct", "ord", "pow", "print", "range", "repr", "reversed", "round", "set",
    "slice", "sorted", "str", "sum", "tuple", "type", "zip", "property", "staticmethod",
    "classmethod", "super", "hasattr", "id", "bytearray", "NotImplemented", "Ellipsis",
    "True", "False", "None",
    "ArithmeticError", "AssertionError", "AttributeError", "BaseException", "Exception",
    "IndexError", "KeyError", "LookupError", "NameError", "NotImplementedError",
    "OverflowError", "RuntimeError", "StopIteration", "TypeError", "ValueError",
    "ZeroDivisionError", "ImportError", "MemoryError", "RecursionError",
)


# --- audit hook: precise reports of what the code tried --------------------------------

_BLOCKED_EVENTS = (
    "subprocess.Popen", "os.system", "os.exec", "os.posix_spawn", "os.spawn", "os.fork",
    "os.forkpty", "os.kill", "os.killpg", "ctypes.dlopen", "ctypes.dlsym",
    "sys.settrace", "sys.setprofile", "os.chroot", "os.setuid", "webbrowser.open",
    "socket.__new__", "socket.bind", "socket.connect", "socket.getaddrinfo",
    "socket.gethostbyname", "socket.sendto", "urllib.Request", "http.client.connect",
)
_PATH_EVENTS = (
    "os.remove", "os.rename", "os.rmdir", "os.mkdir", "os.symlink", "os.link", "os.chmod",
    "os.chown", "os.truncate", "os.utime", "os.chdir", "shutil.rmtree", "shutil.move",
    "shutil.copyfile", "shutil.copytree",
)


def _install_audit_hook(job_dir, read_roots, vw):
    job = job_dir.rstrip("/") + "/"
    roots = tuple(r.rstrip("/") + "/" for r in read_roots)
    write_flags = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_TRUNC
    join, normpath, fspath = os.path.join, os.path.normpath, os.fspath
    write = os.write
    state = {"busy": False}

    def report(message):
        try:
            write(vw, (message[:500] + "\n").encode("utf-8", "replace"))
        except OSError:
            pass

    def resolve(path):
        try:
            p = fspath(path)
        except TypeError:
            return None
        if isinstance(p, bytes):
            p = p.decode("utf-8", "replace")
        return normpath(join(job_dir, p))

    def hook(event, args):
        if state["busy"]:
            return
        state["busy"] = True
        try:
            if event == "open":
                path, mode, flags = (list(args) + [None, None, None])[:3]
                if path is None or isinstance(path, int):
                    return
                p = resolve(path)
                if p is None:
                    return
                writing = bool((flags or 0) & write_flags) or any(c in (mode or "") for c in "wax+")
                inside = (p + "/").startswith(job) or p + "/" == job
                if inside or (not writing and (p + "/").startswith(roots)):
                    return
                report(f"file access outside the job directory: {'write' if writing else 'read'} '{p}'")
                raise PermissionError(f"sandbox: access to '{p}' is not allowed")
            if event in _BLOCKED_EVENTS or event.startswith("socket.") or event.startswith("subprocess."):
                report(f"forbidden operation: {event}")
                raise PermissionError(f"sandbox: {event} is not allowed")
            if event in _PATH_EVENTS:
                for a in args:
                    if isinstance(a, (str, bytes)) or hasattr(a, "__fspath__"):
                        p = resolve(a)
                        if p is not None and not ((p + "/").startswith(job) or p + "/" == job):
                            report(f"file operation outside the job directory: {event} '{p}'")
                            raise PermissionError(f"sandbox: {event} on '{p}' is not allowed")
        finally:
            state["busy"] = False

    sys.addaudithook(hook)


# --- OpenSCAD ----------------------------------------------------------------------------


def _openscad_child(worker, job_dir, limits, vw):
    try:
        _child_fds(job_dir, (vw,))
        os.close(vw)
        worker._confine(job_dir, allow_exec=True, limits=limits)
        os.execv(worker.openscad, ["openscad", "--export-format", "binstl", "-o", "result.stl", "part.scad"])
    except BaseException as e:
        try:
            sys.stderr.write(f"sandbox set-up failed: {e}\n")
        finally:
            os._exit(4)


def _openscad_result(job_dir, status, output, limits):
    stl = os.path.join(job_dir, "result.stl")
    exit_code = os.WEXITSTATUS(status) if os.WIFEXITED(status) else -1
    errors = [line for line in output.splitlines() if line.startswith("ERROR") or "Parser error" in line]
    if exit_code != 0 or not os.path.exists(stl):
        text = errors[0] if errors else (output.strip().splitlines() or [f"openscad exited with {exit_code}"])[-1]
        if "Parser error" in output or "syntax error" in output:
            kind = "syntax"
        elif errors:
            kind = "runtime"
        elif "top level object is empty" in output:
            kind = "no_result"
        else:
            kind = "runtime"
        if exit_code == 4 and "sandbox set-up failed" in output:
            kind = "crash"
        return {"ok": False, "error": {"kind": kind, "message": text[:2000]}}
    checked = _check_stl(stl, limits)
    if checked is not None:
        return {"ok": False, "error": checked}
    return {"ok": True, "stl": stl}


# --- helpers -----------------------------------------------------------------------------


def _default_limits():
    return _limits_of({})


def _limits_of(req):
    def num(key, default, lo, hi):
        try:
            v = float(req.get(key, default))
        except (TypeError, ValueError):
            v = default
        return min(max(v, lo), hi)

    timeout = num("timeout_s", 10.0, 0.1, 600.0)
    return {
        "timeout_s": timeout,
        "cpu_s": max(1.0, timeout),
        "memory_bytes": int(num("memory_mb", 2048, 64, 65536)) << 20,
        "max_file_bytes": int(num("max_output_mb", 64, 1, 4096)) << 20,
        "max_triangles": int(num("max_triangles", 500_000, 100, 50_000_000)),
    }


def _wait(pid, timeout_s):
    """Waits for the job process; kills it after `timeout_s`. Returns (status,
    timed_out, rusage)."""
    deadline = time.monotonic() + timeout_s
    timed_out = False
    try:
        fd = os.pidfd_open(pid)
    except (AttributeError, OSError):
        fd = None
    while True:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            timed_out = True
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            break
        if fd is not None:
            r, _, _ = select.select([fd], [], [], remaining)
            if r:
                break
        else:
            wpid, status, rusage = os.wait4(pid, os.WNOHANG)
            if wpid == pid:
                return status, False, rusage
            time.sleep(min(0.005, remaining))
    if fd is not None:
        os.close(fd)
    _, status, rusage = os.wait4(pid, 0)
    return status, timed_out, rusage


def _send_job(fd, code, req):
    data = json.dumps({"code": code, "req": req}).encode()
    try:
        view = memoryview(data)
        while view:
            n = os.write(fd, view)
            view = view[n:]
    finally:
        os.close(fd)


def _cpu_s(rusage):
    return rusage.ru_utime + rusage.ru_stime


def _read_all(fd, cap):
    chunks, total = [], 0
    os.set_blocking(fd, False)
    while total < cap:
        try:
            b = os.read(fd, min(65536, cap - total))
        except BlockingIOError:
            break
        if not b:
            break
        chunks.append(b)
        total += len(b)
    return b"".join(chunks)


def _open_regular(path):
    """Opens a file the job process wrote, refusing links and anything but a regular
    file (the job could have planted a symlink to a file outside its directory)."""
    fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_CLOEXEC)
    st = os.fstat(fd)
    import stat as _stat

    if not _stat.S_ISREG(st.st_mode) or st.st_nlink != 1:
        os.close(fd)
        raise OSError("not a regular file")
    return fd, st


def _read_text(path, cap):
    try:
        fd, _ = _open_regular(path)
    except OSError:
        return ""
    try:
        return os.read(fd, cap).decode("utf-8", "replace")
    finally:
        os.close(fd)


def _read_json(path):
    try:
        fd, st = _open_regular(path)
    except OSError:
        return None
    try:
        if st.st_size > RESULT_JSON_MAX:
            return None
        data = os.read(fd, RESULT_JSON_MAX)
    finally:
        os.close(fd)
    try:
        obj = json.loads(data)
    except ValueError:
        return None
    return obj if isinstance(obj, dict) else None


def _check_stl(path, limits):
    try:
        fd, st = _open_regular(path)
    except OSError:
        return {"kind": "no_result", "message": "the job wrote no STL"}
    os.close(fd)
    if st.st_size > limits["max_file_bytes"]:
        return {"kind": "output_limit", "message": f"the STL is larger than {limits['max_file_bytes'] >> 20} MiB"}
    if st.st_size < 84:
        return {"kind": "no_result", "message": "the STL is empty"}
    return None


def _error(jid, kind, message, started, line=None):
    err = {"kind": kind, "message": message}
    if line is not None:
        err["line"] = line
    return {"id": jid, "ok": False, "error": err, "ms": {"total": _ms(started)}, "output": ""}


def _ms(t0):
    return round((time.monotonic() - t0) * 1000.0, 3)


def _selftest_read():
    try:
        with open("/etc/hostname", "rb") as f:
            f.read(1)
        return 1  # read: the sandbox failed
    except OSError:
        return 0


def _selftest_socket():
    import socket

    socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    return 1  # still alive: the sandbox failed


# --- main --------------------------------------------------------------------------------


def main(argv):
    root = None
    strict = True
    limits_req = {}
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--root" and args:
            root = args.pop(0)
        elif a == "--weak":
            strict = False
        elif a == "--limits" and args:
            limits_req = json.loads(args.pop(0))
    if not root or not os.path.isdir(root):
        sys.stderr.write("worker: --root DIR is required\n")
        return 2
    # The protocol owns the real stdout; anything a library prints goes to stderr.
    proto = os.fdopen(os.dup(1), "w", buffering=1)
    os.dup2(2, 1)
    w = Worker(root, strict)
    w.standby_limits = _limits_of(limits_req)
    w.warm()
    sandbox_ok = w.caps["landlock_abi"] >= 1 and w.caps["seccomp"] and w.run_selftest()
    ready = w.ready_message()
    ready["sandbox"]["ok"] = sandbox_ok
    if w.threads() != 1:
        ready["sandbox"]["ok"] = sandbox_ok = False
        ready["sandbox"]["problem"] = "the warm worker is multi-threaded; forking it is unsafe"
    if strict and not sandbox_ok:
        ready["type"] = "refused"
        proto.write(json.dumps(ready) + "\n")
        return 3
    proto.write(json.dumps(ready) + "\n")
    import gc

    gc.collect()
    gc.freeze()  # forked jobs then do not touch (and copy) the warm image's objects
    w.prefork()
    for line in sys.stdin:
        line = line.strip()
        if not line:
            continue
        try:
            req = json.loads(line)
        except ValueError:
            proto.write(json.dumps({"id": "", "ok": False, "error": {"kind": "crash", "message": "unreadable job line"}}) + "\n")
            continue
        try:
            res = w.handle(req)
        except Exception as e:  # a worker bug: report it, keep serving
            res = {"id": str(req.get("id", "")), "ok": False, "error": {"kind": "crash", "message": f"worker error: {e}", "trace": traceback.format_exc()[-2000:]}}
        proto.write(json.dumps(res) + "\n")
        w.prefork()
    w.close()
    return 0
