"""Browser tests of the inspector pages that `exactccd inspect ... --html OUT.html` writes (issue 29).

The harness writes the pages and lists them in EXACTCCD_INSPECTOR_PAGES (os.pathsep-separated);
next to PAGE.html it may write PAGE.expect.json, {"toi": [lo, hi] or null}, the TOI the page must
mark. Screenshots go to EXACTCCD_SCREENSHOT_DIR when it is set.

Without EXACTCCD_INSPECTOR_PAGES the tests skip. A missing browser never skips: it fails, saying
what to install (apt-get install chromium chromium-driver python3-selenium).
"""

import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import inspector_check  # noqa: E402

PAGES = [p for p in os.environ.get('EXACTCCD_INSPECTOR_PAGES', '').split(os.pathsep) if p]
needs_pages = pytest.mark.skipif('EXACTCCD_INSPECTOR_PAGES' not in os.environ,
                                 reason='EXACTCCD_INSPECTOR_PAGES is not set (no inspector pages to check)')


def _screenshot_for(page):
    folder = os.environ.get('EXACTCCD_SCREENSHOT_DIR')
    if not folder:
        return None
    return os.path.join(folder, os.path.splitext(os.path.basename(page))[0] + '.png')


@needs_pages
def test_pages_are_listed():
    assert PAGES, 'EXACTCCD_INSPECTOR_PAGES is set but lists no page'
    for page in PAGES:
        assert os.path.isfile(page), 'inspector page %s does not exist' % page


@needs_pages
@pytest.mark.parametrize('page', PAGES, ids=[os.path.basename(p) for p in PAGES])
def test_page_works_in_chromium(page):
    inspector_check.check_page(page, screenshot_path=_screenshot_for(page),
                               expected_toi=inspector_check.read_expectation(page))


@needs_pages
@pytest.mark.parametrize('how', sorted(inspector_check.BREAKS))
def test_page_broken_on_purpose_fails(how, tmp_path):
    """The browser test has teeth: each way of breaking the first page makes check_page fail, for that reason."""
    assert PAGES, 'EXACTCCD_INSPECTOR_PAGES lists no page'
    with open(PAGES[0], encoding='utf-8') as f:
        broken = inspector_check.break_page(f.read(), how)
    path = tmp_path / ('broken-%s.html' % how)
    path.write_text(broken, encoding='utf-8')
    # BrowserMissing is not an AssertionError: a missing browser fails this test instead of passing it.
    with pytest.raises(AssertionError) as failure:
        inspector_check.check_page(str(path))
    assert inspector_check.BREAK_MESSAGES[how] in str(failure.value), (
        'the page broken by "%s" failed for another reason: %s' % (how, failure.value))
