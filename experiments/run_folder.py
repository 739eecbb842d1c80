"""A `dtlab experiment leaderboard` folder read as one whole run. A run writes
data/facts.json last, and a run into a used folder removes the earlier run's files
(facts.json first) before it writes any; so a folder without data/facts.json holds a
run that was interrupted (or is still running), and its files are not read."""
import os
import sys


def require_whole_run(folder, *needed):
    """Exits naming what is missing unless `folder` holds a finished run and each of `needed`."""
    if not os.path.isfile(os.path.join(folder, "data", "facts.json")):
        sys.exit("%s: no data/facts.json, the file a leaderboard run writes last: the run that wrote this folder "
                 "did not finish (interrupted, or still running), so its files are not a whole run" % folder)
    for name in needed:
        if not os.path.isfile(os.path.join(folder, name)):
            sys.exit("%s: no %s in this run" % (folder, name))
