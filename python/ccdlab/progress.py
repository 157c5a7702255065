"""Progress of long calls (`truth(..., progress=...)`): a callable progress(done, total), or
True for a bar: tqdm's when tqdm is installed, else one line on stderr."""
import sys


class _Bar:
    """progress(done, total) drawn as a tqdm bar, or as a line rewritten on stderr."""

    def __init__(self, desc):
        self.desc = desc
        self.bar = None
        self.last = -1
        try:
            import tqdm
            self.tqdm = tqdm.tqdm
        except ImportError:
            self.tqdm = None

    def __call__(self, done, total):
        if self.tqdm is not None:
            if self.bar is None:
                self.bar = self.tqdm(total=total, desc=self.desc)
            self.bar.update(done - self.bar.n)
            return
        percent = 100 * done // max(total, 1)
        if percent != self.last:
            self.last = percent
            print(f"\r{self.desc}: {percent:3d}%", end="", file=sys.stderr, flush=True)

    def close(self):
        if self.bar is not None:
            self.bar.close()
        elif self.tqdm is None and self.last >= 0:
            print(file=sys.stderr)


def with_progress(call, progress, desc, *args, **kwargs):
    """call(*args, progress=callback, **kwargs) where progress is None, a callable, or True
    (a bar named desc, closed when the call ends)."""
    if progress is True:
        bar = _Bar(desc)
        try:
            return call(*args, progress=bar, **kwargs)
        finally:
            bar.close()
    if progress is False:
        progress = None
    return call(*args, progress=progress, **kwargs)
