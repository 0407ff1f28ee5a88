"""The library's tables as Python's: a pandas DataFrame where pandas is installed, else a dict
of numpy arrays."""

from __future__ import annotations

from typing import Any

import numpy as np


def _pandas():
    """pandas, where it is installed."""
    try:
        import pandas
    except ImportError:
        return None
    return pandas


def _array(dtype: str, payload: Any) -> np.ndarray:
    if dtype == "str":
        return np.array(payload, dtype=object)
    return np.frombuffer(payload, dtype={"float64": "<f8", "int64": "<i8", "bool": "?"}[dtype])


def _table(columns: list[tuple[str, str, Any]], index: str | None = None):
    """Columns as a pandas DataFrame where pandas is installed, else a dict of numpy arrays."""
    data = {name: _array(dtype, payload) for name, dtype, payload in columns}
    pd = _pandas()
    if pd is None:
        return data
    frame = pd.DataFrame(data, copy=False)
    return frame.set_index(index) if index else frame


def _frame(columns: list[tuple[str, str, list]], index: str | None = None):
    """Python lists as a table (``f``: float64, ``str``: text)."""
    data = {
        name: np.array(values, dtype=object) if kind == "str" else np.asarray(values, dtype="<f8")
        for name, kind, values in columns
    }
    pd = _pandas()
    if pd is None:
        return data
    frame = pd.DataFrame(data)
    return frame.set_index(index) if index else frame
