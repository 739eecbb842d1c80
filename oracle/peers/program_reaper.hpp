#pragma once
// The parent of every program dtlab runs (spawn_child, oracle/peers/child_process.hpp).
//
// A program's descendants may leave its process group (setsid) and clear their
// environment (env -i), so that neither the group kill nor the inherited DTLAB_GUARD tag
// (kernel/exit_guard.hpp) finds them. They cannot leave their ancestry: a process whose
// parent dies is adopted by its nearest ancestor that is a child subreaper
// (prctl PR_SET_CHILD_SUBREAPER). So dtlab forks a reaper, a small process of its own
// that is a subreaper, and the reaper forks the program:
//
//     dtlab ── reaper (own group, subreaper) ── program (own group) ── ... ── escaped
//
// Every orphan of the program's tree becomes the reaper's child. The reaper waits for the
// program (reaping adopted orphans as they end), and once the program has ended, whatever
// ended it (its own exit, dtlab's group kill at the time limit, the exit watchdog after
// dtlab itself died, even by SIGKILL), it kills the program's group and every child it
// still has, repeatedly, until it has none, then exits as the program did (the same exit
// code, or the same signal), so that dtlab's wait on the reaper reads the program's end.
// The reaper is in no group that dtlab or the watchdog kills and it blocks the terminal's
// signals: after dtlab's death the watchdog kills the program's group, and the reaper
// then ends what is left. A program's reaper has no parent-death signal: Linux sends it
// when the forking thread ends, which a worker thread of dtlab does while dtlab goes on.
// A forked body's reaper (fork_under_reaper: a Python function peer, whose group no
// watchdog lists) has one, as plain forks of dtlab have (kernel/exit_guard.hpp): when
// its parent dies it kills the body's group itself and goes on as above.
//
// The reaper runs between fork and exit without exec, in a copy of a possibly
// multithreaded process: it calls only async-signal-safe functions and system calls.

namespace dtlab {

// In the reaper, first: blocks SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE (the
// program's exec starts it with an empty mask), moves it to a group of its own and
// makes it a child subreaper. With `end_with_parent`, the death of `parent` (the forking
// thread) makes reap_program kill the program's group (SIGUSR1 as the parent-death
// signal; a program forked afterwards must reset SIGUSR1 to its default).
void become_reaper(bool end_with_parent = false, int parent = 0);

// In the reaper, once `program` is forked: keeps no descriptor of dtlab open (stdin,
// stdout and stderr become /dev/null), waits as described above and exits.
[[noreturn]] void reap_program(int program);

}  // namespace dtlab
