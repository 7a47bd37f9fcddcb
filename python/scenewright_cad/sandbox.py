"""The operating-system layers of the sandbox, applied to a job's process after fork.

In order: resource limits (address space, CPU time, file size, open files, no core
dumps); every capability dropped (when the worker runs as root); no_new_privs; a Landlock
domain that allows reading the Python installation and system libraries, reading and
writing only the job's own directory, no TCP at all, and no signals or abstract sockets
leaving the domain; and a seccomp filter that kills the process on any attempt to create
a socket, a process, run a program (except OpenSCAD jobs), trace, mount, load kernel
code, change limits or signal another process.

Everything here is plain `ctypes` against the kernel's system calls (x86_64), so it needs
nothing installed. `probe()` reports what this kernel offers; the worker refuses to run
jobs when a required layer is missing.
"""

import ctypes
import os
import platform
import resource
import struct

_libc = ctypes.CDLL(None, use_errno=True)
_libc.syscall.restype = ctypes.c_long
_libc.prctl.restype = ctypes.c_int

# x86_64 system call numbers.
NR = {
    "read": 0,
    "socket": 41,
    "connect": 42,
    "accept": 43,
    "sendto": 44,
    "recvfrom": 45,
    "sendmsg": 46,
    "recvmsg": 47,
    "shutdown": 48,
    "bind": 49,
    "listen": 50,
    "getsockname": 51,
    "getpeername": 52,
    "socketpair": 53,
    "setsockopt": 54,
    "getsockopt": 55,
    "clone": 56,
    "fork": 57,
    "vfork": 58,
    "execve": 59,
    "kill": 62,
    "rt_sigqueueinfo": 129,
    "mknod": 133,
    "personality": 135,
    "modify_ldt": 154,
    "pivot_root": 155,
    "prctl": 157,
    "adjtimex": 159,
    "setrlimit": 160,
    "chroot": 161,
    "acct": 163,
    "settimeofday": 164,
    "mount": 165,
    "umount2": 166,
    "swapon": 167,
    "swapoff": 168,
    "reboot": 169,
    "sethostname": 170,
    "setdomainname": 171,
    "iopl": 172,
    "ioperm": 173,
    "init_module": 175,
    "delete_module": 176,
    "quotactl": 179,
    "ptrace": 101,
    "syslog": 103,
    "setuid": 105,
    "setgid": 106,
    "setreuid": 113,
    "setregid": 114,
    "setgroups": 116,
    "setresuid": 117,
    "setresgid": 119,
    "setfsuid": 122,
    "setfsgid": 123,
    "capset": 126,
    "tkill": 200,
    "lookup_dcookie": 212,
    "clock_settime": 227,
    "tgkill": 234,
    "mbind": 237,
    "kexec_load": 246,
    "add_key": 248,
    "request_key": 249,
    "keyctl": 250,
    "migrate_pages": 256,
    "mknodat": 259,
    "unshare": 272,
    "move_pages": 279,
    "accept4": 288,
    "rt_tgsigqueueinfo": 297,
    "perf_event_open": 298,
    "recvmmsg": 299,
    "fanotify_init": 300,
    "prlimit64": 302,
    "name_to_handle_at": 303,
    "open_by_handle_at": 304,
    "sendmmsg": 307,
    "setns": 308,
    "process_vm_readv": 310,
    "process_vm_writev": 311,
    "kcmp": 312,
    "finit_module": 313,
    "seccomp": 317,
    "kexec_file_load": 320,
    "bpf": 321,
    "execveat": 322,
    "userfaultfd": 323,
    "pidfd_send_signal": 424,
    "io_uring_setup": 425,
    "io_uring_enter": 426,
    "io_uring_register": 427,
    "open_tree": 428,
    "move_mount": 429,
    "fsopen": 430,
    "fsconfig": 431,
    "fsmount": 432,
    "fspick": 433,
    "pidfd_open": 434,
    "clone3": 435,
    "pidfd_getfd": 438,
    "process_madvise": 440,
    "mount_setattr": 442,
    "landlock_create_ruleset": 444,
    "landlock_add_rule": 445,
    "landlock_restrict_self": 446,
    "memfd_secret": 447,
}

# Killed on sight: networking, process creation, tracing, kernel interfaces, privilege
# and limit changes.
KILL_SYSCALLS = (
    "socket", "socketpair", "connect", "accept", "accept4", "bind", "listen", "sendto",
    "recvfrom", "sendmsg", "recvmsg", "sendmmsg", "recvmmsg", "shutdown", "getsockname",
    "getpeername", "setsockopt", "getsockopt",
    "fork", "vfork", "tkill", "ptrace", "process_vm_readv", "process_vm_writev",
    "pidfd_open", "pidfd_send_signal", "pidfd_getfd", "process_madvise", "kcmp",
    "mount", "umount2", "pivot_root", "chroot", "unshare", "setns", "open_tree",
    "move_mount", "fsopen", "fsconfig", "fsmount", "fspick", "mount_setattr",
    "kexec_load", "kexec_file_load", "init_module", "finit_module", "delete_module", "bpf",
    "perf_event_open", "keyctl", "add_key", "request_key", "userfaultfd", "io_uring_setup",
    "io_uring_enter", "io_uring_register", "reboot", "swapon", "swapoff", "settimeofday",
    "clock_settime", "adjtimex", "sethostname", "setdomainname", "mknod", "mknodat",
    "open_by_handle_at", "name_to_handle_at", "acct", "quotactl", "syslog", "iopl",
    "ioperm", "modify_ldt", "lookup_dcookie", "fanotify_init", "migrate_pages",
    "move_pages", "memfd_secret", "personality",
    "setuid", "setgid", "setreuid", "setregid", "setgroups", "setresuid", "setresgid",
    "setfsuid", "setfsgid", "capset", "setrlimit",
    "landlock_create_ruleset", "landlock_add_rule", "landlock_restrict_self",
)
# Programs: killed in CadQuery jobs, allowed (and confined by Landlock) in OpenSCAD jobs.
EXEC_SYSCALLS = ("execve", "execveat")

AUDIT_ARCH_X86_64 = 0xC000003E
CLONE_THREAD = 0x00010000
ENOSYS = 38

SECCOMP_RET_KILL_PROCESS = 0x80000000
SECCOMP_RET_ERRNO = 0x00050000
SECCOMP_RET_ALLOW = 0x7FFF0000

PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
PR_SET_PDEATHSIG = 1
PR_CAPBSET_DROP = 24
PR_CAP_AMBIENT = 47
PR_CAP_AMBIENT_CLEAR_ALL = 4
SECCOMP_MODE_FILTER = 2

# Landlock access rights.
FS_EXECUTE = 1 << 0
FS_WRITE_FILE = 1 << 1
FS_READ_FILE = 1 << 2
FS_READ_DIR = 1 << 3
FS_REMOVE_DIR = 1 << 4
FS_REMOVE_FILE = 1 << 5
FS_MAKE_CHAR = 1 << 6
FS_MAKE_DIR = 1 << 7
FS_MAKE_REG = 1 << 8
FS_MAKE_SOCK = 1 << 9
FS_MAKE_FIFO = 1 << 10
FS_MAKE_BLOCK = 1 << 11
FS_MAKE_SYM = 1 << 12
FS_REFER = 1 << 13
FS_TRUNCATE = 1 << 14
FS_IOCTL_DEV = 1 << 15
NET_BIND_TCP = 1 << 0
NET_CONNECT_TCP = 1 << 1
SCOPE_ABSTRACT_UNIX_SOCKET = 1 << 0
SCOPE_SIGNAL = 1 << 1
LANDLOCK_RULE_PATH_BENEATH = 1
LANDLOCK_CREATE_RULESET_VERSION = 1

# Rights that apply to regular files (a rule on a file may only use these).
FILE_RIGHTS = FS_EXECUTE | FS_WRITE_FILE | FS_READ_FILE | FS_TRUNCATE | FS_IOCTL_DEV


class SandboxError(Exception):
    pass


def _syscall(name, *args):
    ctypes.set_errno(0)
    r = _libc.syscall(NR[name], *args)
    if r < 0:
        e = ctypes.get_errno()
        raise SandboxError(f"{name} failed: {os.strerror(e)}")
    return r


def landlock_abi():
    """The kernel's Landlock ABI version, or 0 when Landlock is unavailable."""
    if platform.machine() != "x86_64":
        return 0
    r = _libc.syscall(NR["landlock_create_ruleset"], None, ctypes.c_size_t(0), ctypes.c_uint32(LANDLOCK_CREATE_RULESET_VERSION))
    return int(r) if r > 0 else 0


def seccomp_available():
    if platform.machine() != "x86_64":
        return False
    # PR_GET_SECCOMP: 0 when not in seccomp mode (and the prctl exists).
    return _libc.prctl(21, 0, 0, 0, 0) == 0


def probe():
    """What the operating system offers, for the worker's ready message."""
    return {
        "arch": platform.machine(),
        "landlock_abi": landlock_abi(),
        "seccomp": seccomp_available(),
        "root": os.geteuid() == 0,
    }


# --- resource limits ---------------------------------------------------------------


def vm_size_bytes():
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


def set_limits(cpu_s, memory_bytes, max_file_bytes, max_files=256):
    """Limits counted from what the process already maps (the warm CadQuery image)."""
    base = vm_size_bytes()
    limits = [
        (resource.RLIMIT_CPU, (max(1, int(cpu_s)), max(1, int(cpu_s)) + 1)),
        (resource.RLIMIT_AS, (base + memory_bytes, base + memory_bytes)),
        (resource.RLIMIT_FSIZE, (max_file_bytes, max_file_bytes)),
        (resource.RLIMIT_NOFILE, (max_files, max_files)),
        (resource.RLIMIT_CORE, (0, 0)),
        (resource.RLIMIT_MEMLOCK, (0, 0)),
    ]
    for which, value in limits:
        resource.setrlimit(which, value)


# --- capabilities ------------------------------------------------------------------


class _CapHeader(ctypes.Structure):
    _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]


class _CapData(ctypes.Structure):
    _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)]


def drop_capabilities():
    """Empties the bounding, ambient, effective, permitted and inheritable sets."""
    if os.geteuid() != 0:
        return
    for cap in range(0, 64):
        if _libc.prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0:
            break  # past the last capability this kernel knows
    _libc.prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0)
    header = _CapHeader(0x20080522, 0)
    data = (_CapData * 2)()
    _syscall("capset", ctypes.byref(header), ctypes.byref(data))


def no_new_privs():
    if _libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        raise SandboxError("prctl(PR_SET_NO_NEW_PRIVS) failed")


def die_with_parent():
    _libc.prctl(PR_SET_PDEATHSIG, 9, 0, 0, 0)


# --- Landlock ----------------------------------------------------------------------


class _RulesetAttr(ctypes.Structure):
    _fields_ = [("handled_access_fs", ctypes.c_uint64), ("handled_access_net", ctypes.c_uint64), ("scoped", ctypes.c_uint64)]


class _PathBeneath(ctypes.Structure):
    _pack_ = 1
    _fields_ = [("allowed_access", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]


def _fs_rights(abi):
    rights = (1 << 13) - 1  # EXECUTE .. MAKE_SYM
    if abi >= 2:
        rights |= FS_REFER
    if abi >= 3:
        rights |= FS_TRUNCATE
    if abi >= 5:
        rights |= FS_IOCTL_DEV
    return rights


def apply_landlock(abi, read_paths, write_dirs, exec_paths=()):
    """Restricts the process to reading `read_paths`, executing `exec_paths` and
    reading and writing (regular files only) beneath `write_dirs`; on ABI 4+ denies
    every TCP bind and connect, on ABI 6+ every signal and abstract socket that
    would leave the domain."""
    if abi < 1:
        raise SandboxError("Landlock is not available")
    handled = _fs_rights(abi)
    attr = _RulesetAttr(handled, 0, 0)
    size = 8
    if abi >= 4:
        attr.handled_access_net = NET_BIND_TCP | NET_CONNECT_TCP
        size = 16
    if abi >= 6:
        attr.scoped = SCOPE_ABSTRACT_UNIX_SOCKET | SCOPE_SIGNAL
        size = 24
    fd = _syscall("landlock_create_ruleset", ctypes.byref(attr), ctypes.c_size_t(size), ctypes.c_uint32(0))
    try:
        read = FS_READ_FILE | FS_READ_DIR
        write = read | FS_WRITE_FILE | FS_MAKE_REG | FS_MAKE_DIR | FS_REMOVE_FILE | FS_REMOVE_DIR
        if abi >= 3:
            write |= FS_TRUNCATE
        rules = [(p, read) for p in read_paths] + [(p, read | FS_EXECUTE) for p in exec_paths]
        rules += [(p, write) for p in write_dirs]
        for path, rights in rules:
            try:
                pfd = os.open(path, os.O_PATH | os.O_CLOEXEC)
            except OSError:
                continue  # a path this machine does not have
            try:
                if not os.path.isdir(path):
                    rights &= FILE_RIGHTS
                rights &= handled
                rule = _PathBeneath(rights, pfd)
                _syscall("landlock_add_rule", ctypes.c_int(fd), ctypes.c_int(LANDLOCK_RULE_PATH_BENEATH), ctypes.byref(rule), ctypes.c_uint32(0))
            finally:
                os.close(pfd)
        _syscall("landlock_restrict_self", ctypes.c_int(fd), ctypes.c_uint32(0))
    finally:
        os.close(fd)


# --- seccomp -----------------------------------------------------------------------

_LD_W_ABS = 0x20
_JEQ_K = 0x15
_JSET_K = 0x45
_JGE_K = 0x35
_RET_K = 0x06


class _SockFilter(ctypes.Structure):
    _fields_ = [("code", ctypes.c_uint16), ("jt", ctypes.c_uint8), ("jf", ctypes.c_uint8), ("k", ctypes.c_uint32)]


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_uint16), ("filter", ctypes.POINTER(_SockFilter))]


def _assemble(program):
    """`program`: a list of (code, k, jt_label, jf_label) or ("label", name). Jumps name
    labels; None means the next instruction."""
    labels, out = {}, []
    for item in program:
        if item[0] == "label":
            labels[item[1]] = len(out)
        else:
            out.append(item)
    code = []
    for i, (op, k, jt, jf) in enumerate(out):
        def rel(label):
            if label is None:
                return 0
            d = labels[label] - i - 1
            if not 0 <= d <= 255:
                raise SandboxError(f"seccomp jump out of range ({d})")
            return d
        code.append((op, rel(jt), rel(jf), k))
    return code


def seccomp_program(own_pid, allow_exec=False):
    """The filter as (code, jt, jf, k) tuples."""
    args0_lo, args0_hi = 16, 20
    p = [
        (_LD_W_ABS, 4, None, None),
        (_JEQ_K, AUDIT_ARCH_X86_64, None, "kill"),
        (_LD_W_ABS, 0, None, None),
        (_JGE_K, 0x40000000, "kill", None),  # x32 ABI
    ]
    killed = list(KILL_SYSCALLS) + ([] if allow_exec else list(EXEC_SYSCALLS))
    for name in killed:
        p.append((_JEQ_K, NR[name], "kill", None))
    p.append((_JEQ_K, NR["clone3"], "enosys", None))
    p.append((_JEQ_K, NR["clone"], "clone", None))
    for name in ("kill", "tgkill", "rt_sigqueueinfo", "rt_tgsigqueueinfo"):
        p.append((_JEQ_K, NR[name], "own_pid", None))
    p.append((_JEQ_K, NR["prlimit64"], "prlimit", None))
    p.append((_RET_K, SECCOMP_RET_ALLOW, None, None))
    # prlimit64: reading limits only (glibc's getrlimit); never setting them.
    args2_lo, args2_hi = 32, 36
    p.append(("label", "prlimit"))
    p.append((_LD_W_ABS, args2_hi, None, None))
    p.append((_JEQ_K, 0, None, "kill"))
    p.append((_LD_W_ABS, args2_lo, None, None))
    p.append((_JEQ_K, 0, "allow", "kill"))
    # clone: threads only.
    p.append(("label", "clone"))
    p.append((_LD_W_ABS, args0_lo, None, None))
    p.append((_JSET_K, CLONE_THREAD, "allow", "kill"))
    # Signals: to this process only (not its group, not the worker).
    p.append(("label", "own_pid"))
    p.append((_LD_W_ABS, args0_hi, None, None))
    p.append((_JEQ_K, 0, None, "kill"))
    p.append((_LD_W_ABS, args0_lo, None, None))
    p.append((_JEQ_K, own_pid, "allow", "kill"))
    p.append(("label", "enosys"))
    p.append((_RET_K, SECCOMP_RET_ERRNO | ENOSYS, None, None))
    p.append(("label", "allow"))
    p.append((_RET_K, SECCOMP_RET_ALLOW, None, None))
    p.append(("label", "kill"))
    p.append((_RET_K, SECCOMP_RET_KILL_PROCESS, None, None))
    return _assemble(p)


def apply_seccomp(allow_exec=False):
    code = seccomp_program(os.getpid(), allow_exec)
    filters = (_SockFilter * len(code))(*[_SockFilter(c, jt, jf, k) for c, jt, jf, k in code])
    prog = _SockFprog(len(code), filters)
    if _libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.byref(prog), 0, 0) != 0:
        raise SandboxError(f"seccomp filter refused: {os.strerror(ctypes.get_errno())}")


# --- all of it ---------------------------------------------------------------------


def confine(job_dir, read_paths, limits, abi, exec_paths=(), allow_exec=False):
    """Applies every layer, in an order where each step still has what it needs."""
    die_with_parent()
    set_limits(limits["cpu_s"], limits["memory_bytes"], limits["max_file_bytes"])
    drop_capabilities()
    no_new_privs()
    apply_landlock(abi, read_paths, [job_dir], exec_paths)
    apply_seccomp(allow_exec)


def _selftest_struct_sizes():
    assert ctypes.sizeof(_PathBeneath) == 12
    assert ctypes.sizeof(_RulesetAttr) == 24
    assert struct.calcsize("HBBI") == ctypes.sizeof(_SockFilter) == 8
