"""Gymnasium's MultiDiscrete and Box spaces, for when gymnasium is not installed.

Debian 12 ships no gymnasium, so multicpg.env uses these unless ``import gymnasium`` works; they
follow gymnasium.spaces (0.26 to 1.x) in what an agent or checker uses: ``shape``, ``dtype``,
``seed()``, ``sample()`` (the same draws as gymnasium's for the same seed), ``contains()`` and
``in``, ``np_random``, equality. Written here because no Debian package has them.
"""

from __future__ import annotations

from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np

__all__ = ["Box", "MultiDiscrete", "Space"]


def _generator(seed: Optional[int]) -> np.random.Generator:
    """gymnasium.utils.seeding.np_random: a PCG64 generator from the seed's SeedSequence."""
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer))
                             or seed < 0):
        raise ValueError(f"seed: expected a non-negative int or None, got {seed!r}")
    return np.random.Generator(np.random.PCG64(np.random.SeedSequence(seed)))


class Space:
    """A set of values an environment takes or gives: shape, dtype, seed(), sample(),
    contains()."""

    def __init__(self, shape: Tuple[int, ...], dtype: Any, seed: Optional[int] = None):
        self._shape = tuple(int(n) for n in shape)
        self.dtype = np.dtype(dtype)
        self._np_random: Optional[np.random.Generator] = None
        if seed is not None:
            self.seed(seed)

    @property
    def shape(self) -> Tuple[int, ...]:
        """The shape of every value in the space."""
        return self._shape

    @property
    def np_random(self) -> np.random.Generator:
        """The generator sample() draws from (seeded from the OS on first use)."""
        if self._np_random is None:
            self.seed()
        return self._np_random

    @property
    def is_np_flattenable(self) -> bool:
        """Values flatten to one NumPy array (as gymnasium.spaces.flatten does)."""
        return True

    def seed(self, seed: Optional[int] = None) -> list:
        """Seeds sample(); returns [seed] as gymnasium does."""
        self._np_random = _generator(seed)
        return [seed]

    def sample(self, mask: Any = None) -> np.ndarray:
        """A random value of the space."""
        raise NotImplementedError

    def contains(self, x: Any) -> bool:
        """Whether `x` is a value of the space."""
        raise NotImplementedError

    def __contains__(self, x: Any) -> bool:
        return self.contains(x)


class MultiDiscrete(Space):
    """Vectors of whole numbers, element i in start[i] .. start[i] + nvec[i] - 1
    (gymnasium.spaces.MultiDiscrete)."""

    def __init__(self, nvec: Union[Sequence[int], np.ndarray], dtype: Any = np.int64,
                 seed: Optional[int] = None, start: Optional[Sequence[int]] = None):
        self.nvec = np.array(nvec, dtype=dtype, copy=True)
        self.start = (np.zeros(self.nvec.shape, dtype=dtype) if start is None
                      else np.array(start, dtype=dtype, copy=True))
        if self.start.shape != self.nvec.shape:
            raise ValueError("start: must have the shape of nvec")
        if not (self.nvec > 0).all():
            raise ValueError("nvec: every element must be positive")
        super().__init__(self.nvec.shape, dtype, seed)

    def sample(self, mask: Any = None) -> np.ndarray:
        """Uniform in every element (gymnasium's draw)."""
        if mask is not None:
            raise NotImplementedError("MultiDiscrete.sample: masks are not supported here")
        return (self.np_random.random(self.nvec.shape) * self.nvec).astype(self.dtype) + self.start

    def contains(self, x: Any) -> bool:
        """An array (or sequence) of the space's shape with each element in its range."""
        if isinstance(x, Sequence):
            x = np.array(x)
        return bool(isinstance(x, np.ndarray) and x.shape == self.shape and x.dtype != object
                    and np.all(self.start <= x) and np.all(x - self.start < self.nvec))

    def __repr__(self) -> str:
        if np.any(self.start != 0):
            return f"MultiDiscrete({self.nvec}, start={self.start})"
        return f"MultiDiscrete({self.nvec})"

    def __eq__(self, other: Any) -> bool:
        return (isinstance(other, MultiDiscrete) and self.dtype == other.dtype
                and np.array_equal(self.nvec, other.nvec)
                and np.array_equal(self.start, other.start))

    def __len__(self) -> int:
        return len(self.nvec)


class Box(Space):
    """Arrays of real numbers between `low` and `high` element by element
    (gymnasium.spaces.Box); low and high may be scalars broadcast to `shape`."""

    def __init__(self, low: Any, high: Any, shape: Optional[Sequence[int]] = None,
                 dtype: Any = np.float32, seed: Optional[int] = None):
        if shape is None:
            shape = np.broadcast(np.asarray(low), np.asarray(high)).shape
        shape = tuple(int(n) for n in shape)
        self.low = np.full(shape, low, dtype=dtype) if np.isscalar(low) else \
            np.broadcast_to(np.asarray(low, dtype=dtype), shape).copy()
        self.high = np.full(shape, high, dtype=dtype) if np.isscalar(high) else \
            np.broadcast_to(np.asarray(high, dtype=dtype), shape).copy()
        if np.any(self.low > self.high):
            raise ValueError("low: must not be above high")
        self.bounded_below = -np.inf < self.low
        self.bounded_above = np.inf > self.high
        super().__init__(shape, dtype, seed)

    def is_bounded(self, manner: str = "both") -> bool:
        """Whether every element is bounded 'below', 'above' or on 'both' sides."""
        below, above = bool(np.all(self.bounded_below)), bool(np.all(self.bounded_above))
        if manner == "both":
            return below and above
        if manner == "below":
            return below
        if manner == "above":
            return above
        raise ValueError(f"manner: expected 'both', 'below' or 'above', got {manner!r}")

    def sample(self, mask: Any = None) -> np.ndarray:
        """Uniform where bounded on both sides, else exponential or normal (gymnasium's
        draws)."""
        if mask is not None:
            raise NotImplementedError("Box.sample: masks are not supported here")
        high = self.high if self.dtype.kind == "f" else self.high.astype("int64") + 1
        sample = np.empty(self.shape)
        unbounded = ~self.bounded_below & ~self.bounded_above
        upp = ~self.bounded_below & self.bounded_above
        low = self.bounded_below & ~self.bounded_above
        bounded = self.bounded_below & self.bounded_above
        rng = self.np_random
        sample[unbounded] = rng.normal(size=unbounded[unbounded].shape)
        sample[low] = rng.exponential(size=low[low].shape) + self.low[low]
        sample[upp] = -rng.exponential(size=upp[upp].shape) + high[upp]
        sample[bounded] = rng.uniform(low=self.low[bounded], high=high[bounded],
                                      size=bounded[bounded].shape)
        if self.dtype.kind in ("i", "u", "b"):
            sample = np.floor(sample)
        return sample.astype(self.dtype)

    def contains(self, x: Any) -> bool:
        """An array of the space's shape, castable to its dtype, inside the bounds."""
        if not isinstance(x, np.ndarray):
            try:
                x = np.asarray(x, dtype=self.dtype)
            except (ValueError, TypeError):
                return False
        return bool(np.can_cast(x.dtype, self.dtype) and x.shape == self.shape
                    and np.all(x >= self.low) and np.all(x <= self.high))

    def __repr__(self) -> str:
        return f"Box({self.low}, {self.high}, {self.shape}, {self.dtype})"

    def __eq__(self, other: Any) -> bool:
        return (isinstance(other, Box) and self.shape == other.shape
                and self.dtype == other.dtype and np.allclose(self.low, other.low)
                and np.allclose(self.high, other.high))
