"""Run on Dask workers by test_dask.py (importable there through PYTHONPATH)."""
import os
import signal

from velocity.atomic import atomic_write
from velocity.render_task import run_task


def killed_once_marker(job):
    return os.path.join(os.path.dirname(job.output), "killed-once")


def run_task_dying_once(job, task, threads):
    """Runs the task; the first time any task reaches its view 3, the worker process is
    killed (SIGKILL) in the middle of writing that view's colour file."""
    def before_view(job_, task_, view):
        if view != 3:
            return
        try:
            fd = os.open(killed_once_marker(job_), os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            return  # killed once already: this run goes through
        os.write(fd, f"{os.getpid()} {task_.id}".encode())
        os.close(fd)

        def half_then_die(f):
            f.write(b"\x89PNG half a file")
            f.flush()
            os.kill(os.getpid(), signal.SIGKILL)

        atomic_write(job_, job_.view_files(task_.model_key, view)["color"], half_then_die)

    return run_task(job, task, threads, hooks={"before_view": before_view})
