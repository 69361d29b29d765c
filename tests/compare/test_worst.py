"""compare/worst.py: which pixels are the worst, and what each side holds there."""
import numpy as np

from compare.worst import pixel_report, window, worst_pixels


def test_coverage_mismatch_ranks_first_then_delta_e_then_reading_order():
    de = np.zeros((90, 120))
    de[3, 4] = de[3, 80] = 2.0  # a tie: the earlier pixel in reading order wins
    de[40, 40] = 5.0
    mismatch = np.zeros((90, 120), bool)
    mismatch[89, 0] = True
    assert worst_pixels(de, mismatch) == [(89, 0), (40, 40), (3, 4), (3, 80)]


def test_marked_pixels_keep_their_distance_and_identical_images_have_none():
    de = np.zeros((40, 40))
    de[5, 5], de[12, 12], de[30, 30] = 3.0, 2.0, 1.0  # (12, 12) is within 24 pixels of the worst one: skipped
    assert worst_pixels(de, np.zeros_like(de, bool)) == [(5, 5), (30, 30)]
    assert worst_pixels(np.zeros((4, 4)), np.zeros((4, 4), bool)) == []


def test_the_window_is_centred_and_padded_off_the_image():
    image = np.arange(25.0).reshape(5, 5)
    w = window(image, 0, 4, size=3)
    assert np.isnan(w[0]).all() and np.isnan(w[:, 2]).all()
    assert w[1:, :2].tolist() == [[3.0, 4.0], [8.0, 9.0]]
    assert window(np.zeros((4, 4, 3), np.uint8), 2, 2, fill=128).shape == (9, 9, 3)


def test_a_pixel_report_says_who_drew_it():
    ours, ref = np.zeros((2, 2, 3), np.uint8), np.full((2, 2, 3), 255, np.uint8)
    de = np.zeros((2, 2))
    cov_a, cov_b = np.array([[True, True], [False, False]]), np.array([[True, False], [False, False]])
    assert pixel_report(ours, ref, de, cov_a, cov_b, 0, 1).caption() == (
        "x 1, y 0: coverage differs, only ours drew here (ours (0, 0, 0), VTK (255, 255, 255))")
    assert pixel_report(ours, ref, de, cov_a, cov_b, 0, 0).coverage == "shared"
