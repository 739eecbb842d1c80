"""The live child processes of a process, read from /proc (Linux).

Read directly rather than through `ps`: under `make asan` the tests' environment preloads
the ASan runtime, which every program they start inherits, and `ps` (procps) deadlocks at
start-up with it preloaded (seen: blocked on a futex for ever), so a test that polled `ps`
hung until CTest's time-out.
"""
import os


def children(pid=None, skip=("dtlab-watchdog",)):
    """{pid: command name} of the children of `pid` (default: this process) that are not
    zombies, leaving out those named in `skip` (the exit watchdog, kernel/exit_guard.hpp)."""
    parent = os.getpid() if pid is None else pid
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                stat = f.read()
        except OSError:
            continue  # ended meanwhile
        # "pid (comm) state ppid ...": comm may hold spaces and parentheses.
        name = stat[stat.index("(") + 1:stat.rindex(")")]
        state, ppid = stat[stat.rindex(")") + 2:].split()[:2]
        if int(ppid) == parent and state != "Z" and name not in skip:
            found[int(entry)] = name
    return found
