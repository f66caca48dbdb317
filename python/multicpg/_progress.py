"""The progress bar of a long call (learn, tunnel, Simulation.step): tqdm's, in a terminal or
in Jupyter (tqdm.auto picks the widget where ipywidgets is installed, else text).

The compiled module calls a Bar with a report about every 0.1 s while it runs (stage, steps,
total, trials, deviation_deg, finished) and closes it at the end, also when the call is
interrupted. A bar appears only once a call has run DELAY_S, so quick calls print nothing.
"""

import time
import warnings
from typing import Any, Dict, Optional

# Seconds a call runs before its bar appears.
DELAY_S = 0.5


class Bar:
    """One call's bar: steps walked (of `total` when known), trials and the last deviation."""

    def __init__(self, stage: str, total: Optional[int]):
        self.stage = stage
        self.total = total
        self.started = time.monotonic()
        self.bar = None

    def __call__(self, report: Dict[str, Any]) -> None:
        if self.bar is None:
            if time.monotonic() - self.started < DELAY_S:
                return
            with warnings.catch_warnings():  # tqdm.auto warns when it falls back to text
                warnings.simplefilter("ignore")
                from tqdm.auto import tqdm
            self.bar = tqdm(total=self.total, desc=self.stage, unit="step", leave=False)
        self.bar.update(report["steps"] - self.bar.n)
        if report["trials"]:
            self.bar.set_postfix(trials=report["trials"],
                                 E=f"{report['deviation_deg']:.2f}°", refresh=False)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
            self.bar = None
