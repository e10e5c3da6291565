"""The browser tests of the inspector pages (ctest label `browser`): writes pages with the
`exactccd` command (inspect on sample queries, a minimum-separation query and a rigid scene;
a point-plane file and a floor; generate --html on degenerate families; grade --html), records next to each page the TOI that
the command's other subcommands report for the same query (check --out, rigid --json), and runs
test_inspector_page.py on them in headless Chromium.

    python3 tests/browser/run_browser_tests.py --cli build/tools/exactccd [--screenshots DIR]

--screenshots DIR keeps a PNG of every page there (the README's pictures come from it).
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(ROOT, 'tests', 'data')
SAMPLES = os.path.join(DATA, 'sample-queries')

# Queries worth seeing, found by scanning the sample queries with `exactccd inspect --json`:
# a plain contact, a root that fails the inclusion test, float_only's wrong answer, a query
# coplanar throughout.
QUERIES = [
    ('vf_contact', 'unit-tests/vertex-face/data_0_1.csv', 0, 0.0),
    ('ee_root_outside', 'unit-tests/edge-edge/data_0_1.csv', 6, 0.0),
    ('ee_float_only_wrong', 'erleben-cube-cliff-edges/edge-edge/data_0_0.csv', 48, 0.0),
    ('vf_coplanar', 'erleben-cube-cliff-edges/vertex-face/data_0_0.csv', 69, 0.0),
    ('ee_min_separation', 'unit-tests/edge-edge/data_0_1.csv', 6, 1e-3),
]


def run(cli, *args, ok=(0,)):
    r = subprocess.run([cli] + [str(a) for a in args], capture_output=True, text=True)
    if r.returncode not in ok:
        sys.exit('exactccd %s failed (%d): %s' % (' '.join(map(str, args)), r.returncode, r.stderr))
    return r.stdout


def check_toi(cli, work, csv_path, index, delta, *options):
    """The TOI `exactccd check --out` reports for query `index` of csv_path: [lo, hi] or None."""
    out = os.path.join(work, 'check-%d.csv' % len(os.listdir(work)))
    run(cli, 'check', csv_path, '--min-separation', delta, '--out', out, *options, ok=(0, 1))
    with open(out) as f:
        for row in csv.reader(f):
            if row[1] == str(index):
                return None if row[2] == '0' else [float(row[3]), float(row[4])]
    sys.exit('check --out has no row for query %d of %s' % (index, csv_path))


def expect(page, toi):
    with open(os.path.splitext(page)[0] + '.expect.json', 'w') as f:
        json.dump({'toi': toi}, f)


def write_pages(cli, work):
    pages = []
    for name, relative, index, delta in QUERIES:
        path = os.path.join(SAMPLES, relative)
        page = os.path.join(work, name + '.html')
        run(cli, 'inspect', path, '--index', index, '--min-separation', delta, '--html', page)
        expect(page, check_toi(cli, work, path, index, delta))
        pages.append(page)

    # Extreme magnitudes: a vertex falling through a triangle 1e300 across, and the same at
    # the scale of subnormal numbers (a feature 5e-321 across).
    extreme = os.path.join(work, 'extreme', 'vertex-face', 'x.csv')
    os.makedirs(os.path.dirname(extreme))
    with open(extreme, 'w') as f:
        for s in (Fraction(1e300), Fraction(5e-324) * 1024):
            p = [(s / 4, s / 4, s), (0, 0, 0), (s, 0, 0), (0, s, 0)]
            for point in p + [(s / 4, s / 4, -s)] + p[1:]:
                f.write(','.join('%d,%d' % (Fraction(c).numerator, Fraction(c).denominator)
                                 for c in point) + ',1\n')
    for index, name in ((0, 'vf_huge'), (1, 'vf_subnormal')):
        page = os.path.join(work, name + '.html')
        run(cli, 'inspect', extreme, '--index', index, '--html', page)
        expect(page, check_toi(cli, work, extreme, index, 0.0))
        pages.append(page)

    # A point against a turning plane grazing it (a double root), from the point-plane families.
    planes = os.path.join(work, 'planes')
    run(cli, 'generate', '--type', 'pl', '--out', planes, '--per-family', 8)
    page = os.path.join(work, 'pl_graze_turning.html')
    pl_file = os.path.join(planes, 'pl_graze_turning.csv')
    run(cli, 'inspect', pl_file, '--type', 'pl', '--index', 0, '--html', page)
    expect(page, check_toi(cli, work, pl_file, 0, 0.0, '--type', 'pl'))
    pages.append(page)

    # Rigid scenes: a cube turning into a wall (vertex-face) and tipping onto a floor plane
    # (point-plane); the first contact, as `exactccd rigid` reports it (in s).
    for scene_name, name in (('cube_turns_into_wall.json', 'rigid_cube_wall'),
                             ('cube_tips_onto_floor.json', 'rigid_cube_floor')):
        scene = os.path.join(DATA, 'rigid', scene_name)
        page = os.path.join(work, name + '.html')
        run(cli, 'inspect', scene, '--html', page)
        contact = json.loads(run(cli, 'rigid', scene, '--json'))['steps'][0]['contact']
        expect(page, [contact['s_lo'], contact['s_hi']])
        pages.append(page)

    # The degenerate suite's index: one page per family, sharing the folder's scripts.
    suite = os.path.join(work, 'suite')
    run(cli, 'generate', '--out', suite, '--per-family', 8, '--html',
        '--families', 'vf_t0,ee_parallel@s1e-12,vf_grazing')
    with open(os.path.join(suite, 'index.html')) as f:
        assert 'inspect/vf_grazing.html' in f.read()
    for family, kind in (('ee_parallel@s1e-12', 'edge-edge'), ('vf_grazing', 'vertex-face')):
        page = os.path.join(suite, 'inspect', family + '.html')
        data = json.loads(run(cli, 'inspect', os.path.join(suite, family, kind, 'data_0.csv'),
                              '--index', representative(page), '--json'))
        expect(page, None if not data['exact']['collides']
               else [data['exact']['toi_lo'], data['exact']['toi_hi']])
        pages.append(page)

    # A grading report: float_only's answers to a sample file graded; its first page.
    path = os.path.join(SAMPLES, QUERIES[2][1])
    answers = os.path.join(work, 'float_only_answers.txt')
    out = os.path.join(work, 'float_only.csv')
    run(cli, 'check', path, '--mode', 'float_only', '--out', out, ok=(0, 1))
    with open(out) as f, open(answers, 'w') as a:
        for row in csv.reader(f):
            a.write('1,%s\n' % row[3] if row[2] == '1' else '0\n')
    report = os.path.join(work, 'grade_report.html')
    run(cli, 'grade', '--queries', path, '--answers', answers, '--html', report, ok=(1,))
    folder = os.path.join(work, 'grade_report_files')
    first = sorted(p for p in os.listdir(folder) if p.endswith('.html'))[0]
    page = os.path.join(folder, first)
    index = int(first[len('query_'):-len('.html')])
    expect(page, check_toi(cli, work, path, index, 0.0))
    pages.append(page)
    return pages


def index_screenshots(work, folder):
    """PNGs of the two index pages (no script: they only need to load)."""
    sys.path.insert(0, HERE)
    import inspector_check
    import shutil
    driver, profile = inspector_check.start_browser()
    try:
        for page, name in ((os.path.join(work, 'suite', 'index.html'), 'generate_index.png'),
                           (os.path.join(work, 'grade_report.html'), 'grade_report.png')):
            driver.get('file://' + page)
            driver.save_screenshot(os.path.join(folder, name))
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def representative(page):
    """The query index a suite page shows (its data's source index)."""
    with open(page, encoding='utf-8') as f:
        text = f.read()
    start = text.index('id="exactccd-data">') + len('id="exactccd-data">')
    return json.loads(text[start:text.index('</script>', start)])['source']['index']


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--cli', required=True, help='the exactccd command')
    ap.add_argument('--screenshots', help='keep a PNG of every page in this folder')
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix='exactccd-browser-') as work:
        pages = write_pages(os.path.abspath(args.cli), work)
        env = dict(os.environ, EXACTCCD_INSPECTOR_PAGES=os.pathsep.join(pages))
        if args.screenshots:
            os.makedirs(args.screenshots, exist_ok=True)
            env['EXACTCCD_SCREENSHOT_DIR'] = os.path.abspath(args.screenshots)
        status = subprocess.call([sys.executable, '-m', 'pytest', '-q', '-p', 'no:cacheprovider',
                                  os.path.join(HERE, 'test_inspector_page.py')], env=env)
        if args.screenshots:
            index_screenshots(work, env['EXACTCCD_SCREENSHOT_DIR'])
        return status


if __name__ == '__main__':
    sys.exit(main())
