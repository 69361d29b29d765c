"""tests/browser.py: the real-browser helper sees console errors, broken images and outside requests."""
from .browser import broken_images, open_browser, watch


def test_the_browser_helper_reports_what_a_page_test_must_catch(tmp_path):
    (tmp_path / "ok.png").write_bytes(bytes.fromhex(
        "89504e470d0a1a0a0000000d4948445200000001000000010802000000907753de0000000c4944415408d763f8cfc000000301"
        "0100189dd2a20000000049454e44ae426082"))
    page_file = tmp_path / "t.html"
    page_file.write_text("<h1>x</h1><img src='ok.png'><img src='missing.png'>"
                         "<img src='https://cdn.example.com/a.png'><script>console.error('boom')</script>")
    with open_browser() as browser:
        page = browser.new_page()
        log = watch(page)
        page.goto(page_file.as_uri())
        page.wait_for_load_state("load")
        problems = log.problems()
        assert "console: boom" in problems
        assert log.outside_requests == ["https://cdn.example.com/a.png"]
        assert log.failed_requests == [(tmp_path / "missing.png").as_uri()]
        assert sorted(broken_images(page)) == sorted([(tmp_path / "missing.png").as_uri(), "https://cdn.example.com/a.png"])
