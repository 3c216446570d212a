"""Tasks for the sweep fault tests, in a module of their own so that worker processes
import them: a run that kills its own worker process."""
import os
import signal

from acausal import sweepworkers


def kill_at(compiled, values, job):
    """The run of ``values``, as a sweep runs it; where the swept value is ``job["kill"]``
    the worker process is killed instead (SIGKILL, as the kernel's out-of-memory killer
    does), every time, or only the first time when ``job["marker"]`` names a file to
    create then."""
    if next(iter(values.values())) == job["kill"]:
        marker = job.get("marker")
        if marker is None or not os.path.exists(marker):
            if marker is not None:
                open(marker, "w").close()
            os.kill(os.getpid(), signal.SIGKILL)
    return sweepworkers.run_one(compiled, compiled.p.copy(), values, dict(job, task=None))
