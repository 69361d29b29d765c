"""Rows dealt like cards: which rows a band owns (one by one, or in blocks for the opaque raster),
and how many bands a loop uses."""
import numba
import pytest

from renderer.bands import BLOCK_ROWS, SHADING_BANDS, band_offset, first_block_of_band, first_row_of_band, raster_bands, shading_bands


@pytest.mark.parametrize("lo, band, n_bands, first", [(0, 0, 4, 0), (0, 3, 4, 3), (5, 2, 4, 6), (5, 1, 4, 5),
                                                      (6, 1, 4, 9), (7, 0, 1, 7)])
def test_first_row_of_band(lo, band, n_bands, first):
    """Band b owns rows r with r mod n = b: from row 5, band 2 of 4 starts at 6, band 1 at 5; from 6, band 1 at 9."""
    assert first_row_of_band(lo, band, n_bands) == first
    assert first % n_bands == band and lo <= first < lo + n_bands


def test_band_offset_is_the_remainder_with_a_mask_or_a_division():
    """``d mod n`` in 0 … n − 1 for negative and positive ``d``: masked for powers of two (1, 2,
    4, 8, 64), divided for the rest."""
    for n in [1, 2, 3, 4, 5, 6, 7, 8, 12, 64]:
        assert [band_offset(d, n) for d in range(-130, 130)] == [d % n for d in range(-130, 130)]


def test_every_row_goes_to_exactly_one_band():
    """Rows 3..40 dealt to 7 bands: each row once."""
    rows = sorted(r for b in range(7) for r in range(first_row_of_band(3, b, 7), 41, 7))
    assert rows == list(range(3, 41))


def test_raster_bands_default_to_one_per_thread_and_never_exceed_the_rows():
    """Each band walks every triangle: as few bands as threads (a frame's threads are the free cores)."""
    assert raster_bands(10_000) == numba.get_num_threads()
    assert raster_bands(3, 8) == 3 and raster_bands(100, 5) == 5 and raster_bands(0, 5) == 1


def test_shading_bands_are_many_but_at_most_one_per_row():
    assert shading_bands(1000) == SHADING_BANDS == 64
    assert shading_bands(5) == 5 and shading_bands(0) == 1


@pytest.mark.parametrize("block_rows", [BLOCK_ROWS, 64])
@pytest.mark.parametrize("lo, hi, n_bands", [(0, 200, 4), (37, 38, 4), (15, 16, 3), (100, 400, 7), (5, 5, 1)])
def test_blocks_give_every_row_to_exactly_one_band_and_a_small_triangle_to_one(lo, hi, n_bands, block_rows):
    """Rows lo..hi walked as the raster walks them (each band from its first block, every
    n_bands-th block): each row once, in blocks of 16 rows (64 in the walking kernel's
    bands), block j to band j mod n."""
    owner = {}
    for band in range(n_bands):
        block = first_block_of_band(lo, band, n_bands, block_rows)
        assert block % n_bands == band and lo // block_rows <= block < lo // block_rows + n_bands
        while block * block_rows <= hi:
            for row in range(max(lo, block * block_rows), min(hi, block * block_rows + block_rows - 1) + 1):
                assert row not in owner
                owner[row] = band
            block += n_bands
    assert sorted(owner) == list(range(lo, hi + 1))
    assert all(owner[r] == (r // block_rows) % n_bands for r in owner)


def test_loops_over_bands_hand_them_out_one_at_a_time_and_leave_numba_as_it_was():
    """Inside one_band_at_a_time numba's parallel loops take BAND_CHUNK iterations at a time
    (threads take the next band as they come free); after it, numba's setting is back."""
    from renderer.bands import BAND_CHUNK, one_band_at_a_time
    before = numba.get_parallel_chunksize()
    with one_band_at_a_time():
        assert numba.get_parallel_chunksize() == BAND_CHUNK == 1
    assert numba.get_parallel_chunksize() == before
