"""Results of `ccdlab.run`: the ccdlab-results/2 document `ccdlab run` writes, as a dict,
with a table view and the missed contacts of a record (docs/python.md)."""
import math

from ._ccdlab import InputError


class Results(dict):
    """A ccdlab-results/2 document (a dict: every field of the file) with helpers:
    `records`, `methods()`, `to_frame()` (pandas), `missed(method, dt)`."""

    @property
    def records(self):
        return self.get("records", [])

    def methods(self):
        """The method names, in the order of the records."""
        return list(dict.fromkeys(r["method"] for r in self.records))

    def __repr__(self):
        dts = sorted({r["dt"] for r in self.records})
        span = f", dt {dts[0]:g} to {dts[-1]:g} s" if dts else ""
        return (f"<ccdlab.Results {len(self.records)} records: {len(self.methods())} methods x "
                f"{len(dts)} timesteps{span}>")

    def to_frame(self):
        """The records as a pandas DataFrame, one row per record; nested fields (options,
        counters, self_check) become dotted columns. Needs pandas."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Results.to_frame needs pandas (Debian: python3-pandas; "
                              "pip install pandas)") from e
        return pandas.json_normalize(self.records)

    def record(self, method, dt):
        """The record of `method` at timestep `dt` (s; within 1e-9 relative)."""
        found = [r for r in self.records if r["method"] == method]
        if not found:
            raise InputError(f"results: method {method!r}: not in the results ({', '.join(self.methods())})")
        for r in found:
            if math.isclose(r["dt"], dt, rel_tol=1e-9, abs_tol=0.0):
                return r
        dts = ", ".join(format(r["dt"], "g") for r in found)
        raise InputError(f"results: dt {dt!r}: {method} has no record at it ({dts})")

    def missed(self, method, dt):
        """The contacts `method` missed at timestep `dt`: a list of dicts (a, b, enter, exit,
        and static ones with body, polygon when the run lists them). The run must have been
        made with missed_events=True."""
        r = self.record(method, dt)
        if "missed_events" not in r:
            raise InputError("results: missed_events: not in the results "
                             "(run with missed_events=True, or `ccdlab run --list-missed`)")
        return list(r["missed_events"]) + list(r.get("static_missed_events", []))


def missed(results, method, dt):
    """The contacts `method` missed at timestep `dt` in `results` (ccdlab.run's result, or
    any ccdlab-results/2 dict): Results(results).missed(method, dt)."""
    return Results(results).missed(method, dt)
