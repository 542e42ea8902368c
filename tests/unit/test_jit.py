"""The copy loops kernels use instead of slice assignments from arrays (seacable._jit)."""

import numpy as np

from seacable._jit import copy_1d, copy_2d


def test_copy_loops_copy_every_element_into_views_too():
    rng = np.random.default_rng(3)
    src1, src2 = rng.standard_normal(7), rng.standard_normal((4, 3))
    dst1, dst2 = np.zeros(7), np.zeros((4, 3))
    copy_1d(dst1, src1)
    copy_2d(dst2, src2)
    assert dst1.tobytes() == src1.tobytes() and dst2.tobytes() == src2.tobytes()
    # into a strided view (a column, the transpose of a block): the view's elements, the array's others untouched
    block = np.zeros((3, 5))
    copy_1d(block[:, 2], src1[:3])
    copy_2d(block[:, :2].T, src2[:2])
    np.testing.assert_array_equal(block[:, 2], src1[:3])
    np.testing.assert_array_equal(block[:, :2], src2[:2].T)
    assert not block[:, 3:].any()
