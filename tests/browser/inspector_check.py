#!/usr/bin/env python3
"""Real-browser check of a page written by `exactccd inspect FILE --index N --html OUT.html` (issue 29).

Opens the page in headless Chromium (through Selenium and chromedriver) from file://, with no
network, and checks that it works: it initialises without errors, WebGL renders something, the
time slider moves the primitives to the exact positions (computed here independently with
fractions.Fraction and compared bit for bit), the rounding routine behind them is correct on
ties, subnormals and overflow, and the TOI marked on the page is the certified one.

    python3 tests/browser/inspector_check.py PAGE.html [--screenshot OUT.png]
            [--expect-toi LO HI | --expect-no-contact] [--self-test]

Exit status 0 on pass, 1 with the reason on failure. Needs Debian's
`apt-get install chromium chromium-driver python3-selenium`.
"""

import argparse
import json
import os
import random
import re
import shutil
import struct
import sys
import tempfile
import time
import zlib
from fractions import Fraction

INSTALL_HINT = 'apt-get install chromium chromium-driver python3-selenium'

# Headless Chromium with WebGL: ANGLE over SwiftShader (software Vulkan) works headless, as root,
# without a GPU or a display. --enable-unsafe-swiftshader opts in explicitly (the automatic
# fallback to software WebGL is deprecated and warns); the rest keeps the browser off the network.
CHROMIUM_FLAGS = [
    '--headless=new', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update',
    '--disable-sync', '--disable-dev-shm-usage', '--window-size=1400,900',
]
VIEWPORT = (1400, 900)
READY_TIMEOUT = 20.0

# check_page's expected_toi when nothing is expected (None means "expect no contact").
NOT_GIVEN = object()


class BrowserMissing(RuntimeError):
    """Chromium, chromedriver or Selenium is not installed: an environment error, never a pass or a skip."""


# ------------------------------------------------------------------ browser

def find_browser():
    """(chromium binary, chromedriver) paths; EXACTCCD_CHROMIUM / EXACTCCD_CHROMEDRIVER override."""
    def first(env, candidates):
        if os.environ.get(env):
            return os.environ[env] if os.access(os.environ[env], os.X_OK) else None
        for c in candidates:
            path = c if os.path.isabs(c) else shutil.which(c)
            if path and os.access(path, os.X_OK):
                return path
        return None
    # Debian's /usr/bin/chromium is a shell wrapper; the real binary takes the flags as given.
    browser = first('EXACTCCD_CHROMIUM', ['/usr/lib/chromium/chromium', 'chromium', 'chromium-browser', 'google-chrome'])
    driver = first('EXACTCCD_CHROMEDRIVER', ['chromedriver', '/usr/lib/chromium/chromedriver'])
    if not browser or not driver:
        raise BrowserMissing('headless Chromium is needed for the inspector page test but %s is missing; install it with: %s'
                             % ('chromium' if not browser else 'chromedriver', INSTALL_HINT))
    return browser, driver


def start_browser():
    """A fresh headless Chromium with its own temporary profile; returns (driver, profile_dir)."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError as e:
        raise BrowserMissing('Python Selenium is needed for the inspector page test (%s); install it with: %s'
                             % (e, INSTALL_HINT)) from e
    browser, chromedriver = find_browser()
    profile = tempfile.mkdtemp(prefix='exactccd-chromium-')
    options = webdriver.ChromeOptions()
    options.binary_location = browser
    for flag in CHROMIUM_FLAGS + ['--user-data-dir=' + profile]:
        options.add_argument(flag)
    options.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
    try:
        # An explicit chromedriver path: Selenium never looks for (or downloads) one itself.
        driver = webdriver.Chrome(service=Service(chromedriver), options=options)
    except Exception as e:
        shutil.rmtree(profile, ignore_errors=True)
        raise BrowserMissing('could not start headless Chromium (%s, %s): %s\nInstall with: %s'
                             % (browser, chromedriver, e, INSTALL_HINT)) from e
    # The viewport itself is 1400x900 (the window size includes the browser's frame).
    driver.execute_cdp_cmd('Emulation.setDeviceMetricsOverride',
                           {'width': VIEWPORT[0], 'height': VIEWPORT[1], 'deviceScaleFactor': 1, 'mobile': False})
    return driver, profile


# ------------------------------------------------------------------ helpers

def data_from_html(html_text):
    """The inspection JSON embedded in the page, parsed here independently of the browser."""
    m = re.search(r'<script type="application/json" id="exactccd-data">(.*?)</script>', html_text, re.S)
    if not m:
        raise AssertionError('the page has no <script type="application/json" id="exactccd-data"> element')
    try:
        return json.loads(m.group(1))
    except ValueError as e:
        raise AssertionError('the inspection JSON embedded in the page is invalid: %s' % e) from None


def bits(x):
    return struct.pack('>d', float(x)).hex()


def fraction_to_double(q):
    """Correctly rounded (CPython's int / int true division rounds correctly, subnormals included)."""
    try:
        return float(q)
    except OverflowError:
        return float('inf') if q > 0 else float('-inf')


def exact(s):
    """An exact coordinate: a string "num/den" or "num" (or a JSON number, taken as the double it is)."""
    return Fraction(s) if isinstance(s, (int, float)) else Fraction(s.strip())


def png_colour_count(png, limit=16):
    """Distinct pixel colours in a PNG (8-bit RGB or RGBA), counting up to limit. No PIL needed."""
    assert png[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
    pos, idat, width = 8, [], None
    while pos < len(png):
        n, kind = struct.unpack('>I4s', png[pos:pos + 8])
        body = png[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            width, height, depth, ctype = struct.unpack('>IIBB', body[:10])
            if depth != 8 or ctype not in (2, 6):
                raise AssertionError('unexpected PNG format (depth %d, colour type %d)' % (depth, ctype))
            bpp = 3 if ctype == 2 else 4
        elif kind == b'IDAT':
            idat.append(body)
        pos += 12 + n
    raw, stride = zlib.decompress(b''.join(idat)), width * bpp
    prev, colours = bytearray(stride), set()
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif f == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, prev))
        elif f == 3:
            for i in range(stride):
                line[i] = (line[i] + ((line[i - bpp] if i >= bpp else 0) + prev[i]) // 2) & 255
        elif f == 4:
            for i in range(stride):
                a, b, c = (line[i - bpp] if i >= bpp else 0), prev[i], (prev[i - bpp] if i >= bpp else 0)
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        colours.update(bytes(line[i:i + 3]) for i in range(0, stride, bpp))
        if len(colours) >= limit:
            return len(colours)
        prev = line
    return len(colours)


def rounding_cases(seed=29):
    """(numerator, denominator) pairs around every hard case of rational -> double rounding."""
    p52, p53 = 2 ** 52, 2 ** 53
    cases = [(1, 3), (2, 3), (-1, 3), (1, 10), (7, 1), (0, 5), (-0, 7), (10 ** 30, 7), (-(10 ** 30), 7),
             (p53 + 1, 1), (p53 + 3, 1), (-(p53 + 1), 1), (2 * p53 + 2, 2), (p53 + 1, 2 ** 60),   # ties to even
             (1, 2 ** 1074), (1, 2 ** 1075), (3, 2 ** 1075), (5, 2 ** 1076), (1, 3 * 2 ** 1074),     # subnormals
             (2, 3 * 2 ** 1074), (-3, 2 ** 1075), (p52 - 1, 2 ** 1074), (2 * p53 - 1, 2 ** 1076),
             (p53 - 1, 2 ** 1075), (1, 2 ** 1100), (-1, 2 ** 1100),
             ((p53 - 1) * 2 ** 971, 1), (2 ** 1024 - 2 ** 970, 1), (2 ** 1024 - 2 ** 970 - 1, 1),   # overflow
             (-(2 ** 1024 - 2 ** 970), 1), (2 ** 1030, 3), (1, -3)]
    rng = random.Random(seed)
    for _ in range(240):
        n = rng.getrandbits(rng.randint(1, 1200)) * rng.choice((1, -1))
        d = rng.getrandbits(rng.randint(1, 1200)) or 1
        shift = rng.choice((0, 0, rng.randint(-1100, 1100)))
        cases.append((n << shift, d) if shift >= 0 else (n, d << -shift))
    for _ in range(60):   # exact ties and their neighbours in every range
        m, e = rng.getrandbits(53) | p52, rng.randint(-1130, 960)
        n, d = (2 * m + 1) * 2 ** max(e, 0), 2 ** max(-e, 0) * 2
        cases += [(n, d), (n + 1, d + 1 if d > 1 else d), (n * 3 - 1, d * 3)]
    return cases


# ------------------------------------------------------------------ the check

JS_BITS = ('const bits = x => { const v = new DataView(new ArrayBuffer(8)); v.setFloat64(0, x);'
           ' return v.getBigUint64(0).toString(16).padStart(16, "0"); };'
           'const I = window.exactccdInspector;')


def _state(driver):
    return driver.execute_script(
        'const a = window.exactccdInspector;'
        'return a ? {ready: a.ready === true, errors: (a.errors || []).map(String), webgl: a.webgl,'
        ' renderCount: a.renderCount} : null')


def _severe(driver):
    return ['%s' % e.get('message') for e in driver.get_log('browser') if e.get('level') == 'SEVERE']


def _at_slider(driver, value):
    return driver.execute_script(JS_BITS + (
        'const s = document.getElementById("time-slider"); s.value = String(arguments[0]);'
        's.dispatchEvent(new Event("input", {bubbles: true}));'
        'return {time: bits(I.time()), positions: I.positions().map(p => p.map(bits)),'
        ' shown: document.getElementById("time-value").textContent};'), value)


def _at_time(driver, t):
    return driver.execute_script(JS_BITS + (
        'I.setTime(arguments[0]);'
        'return {time: bits(I.time()), positions: I.positions().map(p => p.map(bits)),'
        ' slider: document.getElementById("time-slider").value};'), t)


def _from_bits(h):
    return struct.unpack('>d', bytes.fromhex(h))[0]


def exact_positions(data, t):
    """x0 + t (x1 - x0) at the exact value of the double t, correctly rounded, for every point."""
    n, pe, T = len(data['labels']), data['points_exact'], Fraction(t)
    out = []
    for i in range(n):
        x0, x1 = [exact(s) for s in pe[i]], [exact(s) for s in pe[n + i]]
        out.append([bits(fraction_to_double(a + T * (b - a))) for a, b in zip(x0, x1)])
    return out


def _compare_positions(what, got, want, labels):
    if len(got) != len(want):
        raise AssertionError('%s: positions() has %d points, expected %d (%s)' % (what, len(got), len(want), labels))
    for i, (g, w) in enumerate(zip(got, want)):
        if g != w:
            raise AssertionError('%s: point %s is drawn at %r but exactly rounded it is %r (bit patterns %s vs %s)'
                                 % (what, labels[i], [_from_bits(b) for b in g], [_from_bits(b) for b in w], g, w))


def check_page(html_path, screenshot_path=None, expected_toi=NOT_GIVEN, timeout=READY_TIMEOUT):
    """Check one inspector page in headless Chromium; AssertionError with the reason on failure.

    expected_toi: a (lo, hi) pair of floats, or None for "no contact"; leave it out to check
    only that the marked TOI is data.result's. Returns a dict of timings and facts about the run.
    """
    html_path = os.path.abspath(html_path)
    with open(html_path, encoding='utf-8') as f:
        html_text = f.read()
    started = time.monotonic()
    driver, profile = start_browser()
    facts = {'page': html_path, 'browser_start_s': round(time.monotonic() - started, 2)}
    try:
        driver.get('file://' + html_path)
        deadline, st = time.monotonic() + timeout, None
        while time.monotonic() < deadline:
            st = _state(driver)
            if st and (st['ready'] or st['errors']):
                break
            time.sleep(0.1)
        if st and st['errors']:
            raise AssertionError('the page reported errors:\n  ' + '\n  '.join(st['errors']))
        if not st or not st['ready']:
            raise AssertionError('exactccdInspector.ready did not become true within %g s (state %r; severe log: %r)'
                                 % (timeout, st, _severe(driver)))
        severe = _severe(driver)
        if severe:
            raise AssertionError('the browser log has SEVERE entries:\n  ' + '\n  '.join(severe))
        facts['ready_s'] = round(time.monotonic() - started, 2)

        # WebGL: CI must have it, so "unavailable" is a failure, with the reason spelled out.
        if st['webgl'] is not True:
            raise AssertionError('WebGL is unavailable in headless Chromium, so the 3D view was not drawn (the page says so). '
                                 'CI must provide WebGL; these flags give it through SwiftShader: ' + ' '.join(CHROMIUM_FLAGS))
        if not st['renderCount'] or st['renderCount'] <= 0:
            raise AssertionError('WebGL is available but the page rendered no frame (renderCount %r)' % st['renderCount'])
        from selenium.webdriver.common.by import By
        canvas_png = driver.find_element(By.CSS_SELECTOR, '#view canvas').screenshot_as_png
        colours = png_colour_count(canvas_png)
        if colours < 2:
            raise AssertionError('the 3D view is a single colour: WebGL drew nothing visible')
        facts['canvas_colours_at_least'] = colours
        # The query itself is in view: some point's label is placed (a view scaled to infinity
        # or to nothing draws only the background and the grid).
        placed = driver.execute_script("return document.querySelectorAll('#labels .lbl').length;")
        if not placed:
            raise AssertionError('no point of the query is in the 3D view (no label placed): the framing failed')
        facts['labels_in_view'] = placed

        data = data_from_html(html_text)
        labels, t_max = data['labels'], float(data['t_max'])

        # The page's rational -> double rounding against CPython's correctly rounded division.
        cases = rounding_cases()
        got = driver.execute_script(JS_BITS + 'return arguments[0].map(([n, d]) => bits(I.roundRational(n, d)));',
                                    [[str(n), str(d)] for n, d in cases])
        for (n, d), g in zip(cases, got):
            want = bits(fraction_to_double(Fraction(n, d)))
            if g != want:
                raise AssertionError('the page rounds %d/%d to %r but the nearest double (ties to even) is %r'
                                     % (n, d, _from_bits(g), _from_bits(want)))
        facts['rounding_cases'] = len(cases)

        # The slider: time = t_max * value / steps as a double, and the positions drawn at that time.
        steps = int(driver.execute_script('return Number(document.getElementById("time-slider").max)'))
        seen = []
        for value in (steps * 3 // 10, steps * 7 // 9):
            r = _at_slider(driver, value)
            t = _from_bits(r['time'])
            if r['time'] != bits(t_max * value / steps):
                raise AssertionError('slider at %d/%d: time() is %r, expected t_max * value / steps = %r'
                                     % (value, steps, t, t_max * value / steps))
            if float(r['shown']) != t:
                raise AssertionError('the printed time %r does not read back as time() %r' % (r['shown'], t))
            if data.get('motion', 'linear') != 'samples':
                _compare_positions('slider at %d/%d (t = %r)' % (value, steps, t), r['positions'], exact_positions(data, t), labels)
            seen.append(r['positions'])
        moves = t_max > 0 and _moves(data)
        if moves and seen[0] == seen[1] and _expected_differ(data, steps):
            raise AssertionError('moving the slider did not move the primitives (positions() unchanged)')
        facts['slider_moves_primitives'] = seen[0] != seen[1]

        if data.get('motion', 'linear') == 'samples':   # positions at sample times are the given doubles
            tr = data['trajectory']
            at = {len(tr['times']) // 3, len(tr['times']) - 1}
            if data['result'].get('toi_lo') in tr['times']:   # the exact positions at the TOI, when sampled there
                at.add(tr['times'].index(data['result']['toi_lo']))
            for k in sorted(at):
                r = _at_time(driver, tr['times'][k])
                want = [[bits(x) for x in p] for p in tr['positions'][k][:len(labels)]]
                _compare_positions('setTime(sample time %r)' % tr['times'][k], r['positions'], want, labels)
        elif data['result'].get('toi_lo') is not None:   # and exactly at the TOI
            r = _at_time(driver, data['result']['toi_lo'])
            _compare_positions('setTime(toi_lo)', r['positions'], exact_positions(data, data['result']['toi_lo']), labels)

        # The TOI marked in the plot and the panel.
        marked = driver.execute_script(JS_BITS + 'const m = I.markedToi(); return m && [bits(m.lo), bits(m.hi)];')
        res = data['result']
        want = None if res.get('toi_lo') is None else [bits(res['toi_lo']), bits(res['toi_hi'])]
        if marked != want:
            raise AssertionError('the page marks the TOI %s but data.result says %s' % (_toi_text(marked), _toi_text(want)))
        if expected_toi is not NOT_GIVEN:
            exp = None if expected_toi is None else [bits(expected_toi[0]), bits(expected_toi[1])]
            if marked != exp:
                raise AssertionError('the page marks the TOI %s but %s was expected' % (_toi_text(marked), _toi_text(exp)))

        if screenshot_path:
            driver.execute_script('window.exactccdInspector.setTime(arguments[0])',
                                  res['toi_lo'] if res.get('toi_lo') is not None else 0.0)
            time.sleep(0.3)   # let the requested frame render
            os.makedirs(os.path.dirname(os.path.abspath(screenshot_path)), exist_ok=True)
            if not driver.save_screenshot(screenshot_path):
                raise AssertionError('could not save the screenshot to ' + screenshot_path)
        severe = _severe(driver)
        if severe:
            raise AssertionError('the browser log has SEVERE entries after the checks:\n  ' + '\n  '.join(severe))
        errors = _state(driver)['errors']
        if errors:
            raise AssertionError('the page reported errors during the checks:\n  ' + '\n  '.join(errors))
        facts['total_s'] = round(time.monotonic() - started, 2)
        return facts
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def _moves(data):
    if data.get('motion', 'linear') == 'samples':
        ps = data['trajectory']['positions']
        return any(p != ps[0] for p in ps)
    n, pe = len(data['labels']), data['points_exact']
    return any(exact(a) != exact(b) for i in range(n) for a, b in zip(pe[i], pe[n + i]))


def _expected_differ(data, steps):
    """Whether the exact positions at the two slider values round to different doubles (sub-ulp motions do not)."""
    if data.get('motion', 'linear') == 'samples':
        return True
    t_max = float(data['t_max'])
    return exact_positions(data, t_max * (steps * 3 // 10) / steps) != exact_positions(data, t_max * (steps * 7 // 9) / steps)


def _toi_text(pair):
    return 'none (no contact)' if pair is None else '[%r, %r]' % (_from_bits(pair[0]), _from_bits(pair[1]))


def read_expectation(page):
    """The harness's PAGE.expect.json, {"toi": [lo, hi] or null}, as an expected_toi; NOT_GIVEN when absent."""
    path = os.path.splitext(page)[0] + '.expect.json'
    if not os.path.exists(path):
        return NOT_GIVEN
    with open(path) as f:
        expect = json.load(f)
    if 'toi' not in expect:
        return NOT_GIVEN
    return None if expect['toi'] is None else (float(expect['toi'][0]), float(expect['toi'][1]))


# ------------------------------------------------------------------ pages broken on purpose

MAIN_SCRIPT = '<script id="exactccd-main">'


def _break_throw(html):
    if MAIN_SCRIPT not in html:
        raise ValueError('no %s in the page' % MAIN_SCRIPT)
    return html.replace(MAIN_SCRIPT, MAIN_SCRIPT + '\nthrow new Error("broken on purpose");', 1)


def _break_json(html):
    m = re.search(r'(<script type="application/json" id="exactccd-data">)(.*?)(</script>)', html, re.S)
    if not m:
        raise ValueError('no data element in the page')
    return html[:m.start(2)] + m.group(2)[:len(m.group(2)) // 2] + html[m.end(2):]


def _break_rounding(html):
    # The page's round-half-to-even test turned into round-half-up: only ties change.
    old = '(r2 === den && (q & 1n) === 1n)'
    if old not in html:
        raise ValueError('the rounding routine changed; update break_page("rounding")')
    return html.replace(old, '(r2 === den)', 1)


def _break_one_ulp(html):
    # Positions one ulp off, as drawn: the bit-for-bit comparison must notice.
    hook = ('<script>(function () { const a = window.exactccdInspector, f = a.positions;'
            ' a.positions = () => f().map(p => p.map(x => x === 0 ? Number.MIN_VALUE : x * (1 + Number.EPSILON))); })();</script>')
    return html.replace('</body>', hook + '\n</body>', 1)


def _break_webgl(html):
    # A browser without WebGL: the page must cope, and the check must fail saying so.
    hook = ('<script>(function () { const g = HTMLCanvasElement.prototype.getContext;'
            ' HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {'
            ' return /webgl/.test(kind) ? null : g.call(this, kind, ...rest); }; })();</script>')
    return html.replace('<head>', '<head>\n' + hook, 1)


BREAKS = {'throw': _break_throw, 'json': _break_json, 'rounding': _break_rounding,
          'one_ulp': _break_one_ulp, 'no_webgl': _break_webgl}
# What the failure message must mention, so that each page fails for the right reason.
BREAK_MESSAGES = {'throw': 'broken on purpose', 'json': 'JSON', 'rounding': 'nearest double',
                  'one_ulp': 'exactly rounded', 'no_webgl': 'WebGL is unavailable'}


def break_page(html_text, how='throw'):
    """The page's text broken on purpose in one of BREAKS' ways."""
    return BREAKS[how](html_text)


def self_test(page, workdir=None):
    """check_page must fail on every broken variant of page, for the expected reason."""
    with open(page, encoding='utf-8') as f:
        text = f.read()
    if workdir is None:
        with tempfile.TemporaryDirectory(prefix='exactccd-broken-') as tmp:
            return self_test(page, tmp)
    for how in sorted(BREAKS):
        broken = os.path.join(workdir, 'broken-%s.html' % how)
        with open(broken, 'w', encoding='utf-8') as f:
            f.write(break_page(text, how))
        try:
            check_page(broken)
        except AssertionError as e:
            if BREAK_MESSAGES[how] not in str(e):
                raise AssertionError('the page broken by "%s" failed, but not for the expected reason: %s' % (how, e)) from None
            continue
        raise AssertionError('the page broken on purpose ("%s") passed the check' % how)


# ------------------------------------------------------------------ command line

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('page')
    ap.add_argument('--screenshot', metavar='OUT.png')
    g = ap.add_mutually_exclusive_group()
    g.add_argument('--expect-toi', nargs=2, type=float, metavar=('LO', 'HI'))
    g.add_argument('--expect-no-contact', action='store_true')
    ap.add_argument('--self-test', action='store_true', help='also check that broken variants of the page fail')
    args = ap.parse_args(argv)
    expected = None if args.expect_no_contact else tuple(args.expect_toi) if args.expect_toi else NOT_GIVEN
    try:
        facts = check_page(args.page, args.screenshot, expected)
        if args.self_test:
            self_test(args.page)
    except (AssertionError, BrowserMissing, OSError) as e:
        print('FAIL %s: %s' % (args.page, e), file=sys.stderr)
        return 1
    print('PASS %s (%s)' % (args.page, ', '.join('%s %s' % kv for kv in facts.items() if kv[0] != 'page')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
