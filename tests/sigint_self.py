"""The Python Ctrl-C probe of tests/finds2_cli.sh and tests/finds2_variants.sh.

interrupted_within(when, limit, call): sends this process SIGINT `when` seconds after
starting call(), prints how long after the signal the KeyboardInterrupt came, and returns
the exit status: 0 if it came within `limit` seconds, 1 if it came later or not at all.
"""
import os
import signal
import threading
import time


def interrupted_within(when, limit, call):
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    threading.Timer(when, interrupt).start()
    try:
        call()
        print("no interrupt")
    except KeyboardInterrupt:
        late = time.monotonic() - sent[0]
        print("interrupted %.3f s after the signal" % late)
        return 0 if late < limit else 1
    return 1
