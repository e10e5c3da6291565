#!/usr/bin/env python3
"""Writes the seed corpus of the libFuzzer harnesses (tests/fuzz/corpus/) from the shipped data
sets: real queries (sample queries, degenerate suite, scene queries) and malformed variants of
them. Deterministic; run from anywhere: python3 tests/fuzz/make_corpus.py"""
import json
import pathlib
import struct
from fractions import Fraction

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
CORPUS = ROOT / "tests" / "fuzz" / "corpus"

# (name, file below tests/data, query index): colliding and free queries of both types,
# touching at t = 0 and t = 1, coplanar motion, scaled and translated degenerate variants.
QUERIES = [
    ("sample_vf_free", "sample-queries/unit-tests/vertex-face/data_0_0.csv", 0),
    ("sample_vf_hit", "sample-queries/unit-tests/vertex-face/data_0_0.csv", 12),
    ("sample_ee_hit", "sample-queries/unit-tests/edge-edge/data_0_0.csv", 1),
    ("sample_ee_spike", "sample-queries/erleben-spike-crack/edge-edge/data_0_0.csv", 3),
    ("suite_vf_t0", "degenerate-suite/vf_t0/vertex-face/data_0.csv", 0),
    ("suite_vf_coplanar", "degenerate-suite/vf_coplanar/vertex-face/data_0.csv", 1),
    ("suite_vf_sliding_face", "degenerate-suite/vf_sliding_face/vertex-face/data_0.csv", 0),
    ("suite_vf_grazing_s1e-12", "degenerate-suite/vf_grazing@s1e-12/vertex-face/data_0.csv", 0),
    ("suite_ee_parallel", "degenerate-suite/ee_parallel/edge-edge/data_0.csv", 0),
    ("suite_ee_collinear_t1e8", "degenerate-suite/ee_collinear@t1e8/edge-edge/data_0.csv", 2),
    ("suite_ee_t1", "degenerate-suite/ee_t1/edge-edge/data_0.csv", 1),
]


def rows_of(path, index):
    rows = [line.strip() for line in (DATA / path).read_text().splitlines() if line.strip()]
    return rows[8 * index: 8 * index + 8]


def doubles_of(rows):
    out = []
    for row in rows:
        f = [int(x) for x in row.split(",")]
        for k in range(3):
            value = Fraction(f[2 * k], f[2 * k + 1])
            assert Fraction(float(value)) == value, "not a double: " + row
            out.append(float(value))
    return out


def write(folder, name, data):
    path = CORPUS / folder / name
    path.write_bytes(data if isinstance(data, bytes) else data.encode())


def api_input(type_bit, coordinates, t_max=None, width=None):
    flags = type_bit | (2 if t_max is not None else 0) | (4 if width is not None else 0)
    return (bytes([flags]) + struct.pack("<24d", *coordinates) +
            struct.pack("<2d", 1.0 if t_max is None else t_max, 0.0 if width is None else width))


def main():
    for folder in ("query_file", "ccd_api", "answers_file", "suite_manifest"):
        for old in (CORPUS / folder).glob("*"):
            old.unlink()

    # query_file: real queries, one per file, then files of several queries and malformed ones.
    texts = {}
    for name, path, index in QUERIES:
        texts[name] = "\n".join(rows_of(path, index)) + "\n"
        write("query_file", name + ".csv", texts[name])
    hit, free = texts["sample_vf_hit"], texts["sample_vf_free"]
    write("query_file", "two_queries_blank_line_crlf.csv",
          (hit + "\n" + free).replace("\n", "\r\n"))
    write("query_file", "spaces_and_signs.csv", hit.replace(",", " , +", 3))
    write("query_file", "empty.csv", "")
    write("query_file", "bad_six_columns.csv", hit.replace(",1\n", "\n", 1))
    write("query_file", "bad_zero_denominator.csv", free.replace(",1,", ",0,", 1))
    write("query_file", "bad_truth_two.csv", hit.replace(",1\n", ",2\n", 1))
    write("query_file", "bad_truth_differs.csv", hit.replace(",1\n", ",0\n", 1))
    write("query_file", "bad_cut_short.csv", "\n".join(hit.splitlines()[:5]) + "\n")
    write("query_file", "bad_blank_inside.csv", hit.replace("\n", "\n\n", 1))
    write("query_file", "bad_not_integer.csv", free.replace("1", "1.5", 1))
    write("query_file", "bad_nan.csv", free.replace("1", "nan", 1))
    write("query_file", "huge_numerator.csv", free.replace("1,", "9" * 400 + ",", 1))
    write("query_file", "not_a_double.csv", free.replace(",1,", ",3,", 1))

    # ccd_api: the same queries as raw doubles, also on [0, 1/2] and with a coarse width; and
    # the rejected options and coordinates.
    for name, path, index in QUERIES:
        v = doubles_of(rows_of(path, index))
        type_bit = 1 if "/edge-edge/" in path else 0
        write("ccd_api", name + ".bin", api_input(type_bit, v))
        if name in ("sample_vf_hit", "sample_ee_hit", "suite_vf_coplanar", "suite_ee_t1"):
            write("ccd_api", name + "_tmax_half.bin", api_input(type_bit, v, t_max=0.5))
            write("ccd_api", name + "_width_1e-3.bin", api_input(type_bit, v, width=1e-3))
    v = doubles_of(rows_of(QUERIES[1][1], QUERIES[1][2]))
    write("ccd_api", "bad_nan_coordinate.bin", api_input(0, [float("nan")] + v[1:]))
    write("ccd_api", "bad_infinite_coordinate.bin", api_input(0, v[:5] + [float("inf")] + v[6:]))
    write("ccd_api", "t_max_zero.bin", api_input(0, v, t_max=0.0))  # the state at t = 0
    write("ccd_api", "bad_t_max_negative.bin", api_input(0, v, t_max=-2.0 ** -1074))
    write("ccd_api", "bad_t_max_above_one.bin", api_input(0, v, t_max=1.5))
    write("ccd_api", "bad_negative_width.bin", api_input(0, v, width=-1e-9))
    write("ccd_api", "subnormal_coordinates.bin",
          api_input(0, [x * 2.0 ** -1040 for x in v]))
    write("ccd_api", "zeros.bin", b"")

    # answers_file: `exactccd grade`'s format, good and bad.
    answers = {
        "three.txt": "0\n1\n1,0.5\n",
        "crlf_spaces.txt": "0\r\n 1 , 0.25 \r\n1\r\n",
        "exponents.txt": "1,1e-3\n1,2.5E-1\n1,+0.0\n1,.5\n",
        "no_final_newline.txt": "0\n1,1",
        "empty.txt": "",
        "bad_verdict.txt": "0\n2\n",
        "bad_toi_on_zero.txt": "0,0.5\n",
        "bad_toi_text.txt": "1,abc\n",
        "bad_toi_negative.txt": "1,-0.25\n",
        "bad_toi_above_t_max.txt": "1,1.0000000000000002\n",
        "bad_toi_hex_inf_nan.txt": "1,0x1p-1\n1,inf\n1,nan\n",
        "bad_exponent_too_large.txt": "1,1e-100001\n",
        "bad_blank_line.txt": "0\n\n1\n",
    }
    for name, text in answers.items():
        write("answers_file", name, text)

    # suite_manifest: the generator's format naming the harness's one family "vf_t0" (2 queries,
    # 1 collision), and manifests that must be refused with a clear message.
    family = json.loads((DATA / "degenerate-suite" / "manifest.json").read_text())["families"]
    vf_t0 = next(f for f in family if f["name"] == "vf_t0")
    vf_t0 = dict(vf_t0, queries=2, collisions=1)
    good = {"generator": "exactccd generate", "seed": 1, "per_family": 14, "families": [vf_t0]}
    write("suite_manifest", "good.json", json.dumps(good, indent=2) + "\n")
    minimal = {"families": [{"name": "vf_t0", "queries": 2}]}
    write("suite_manifest", "minimal.json", json.dumps(minimal))
    absent = {"families": [{"name": "vf_t0", "queries": 2}, {"name": "absent", "queries": 0}]}
    write("suite_manifest", "empty_family_absent.json", json.dumps(absent))
    bad = {
        "bad_not_json.json": "{\"families\": [",
        "bad_not_object.json": "[1, 2]",
        "bad_no_families.json": "{\"seed\": 1}",
        "bad_families_empty.json": "{\"families\": []}",
        "bad_name_dotdot.json": json.dumps({"families": [{"name": "..", "queries": 0}]}),
        "bad_name_slash.json": json.dumps({"families": [{"name": "vf_t0/../vf_t0", "queries": 2}]}),
        "bad_name_missing.json": json.dumps({"families": [{"queries": 2}]}),
        "bad_name_twice.json": json.dumps({"families": [minimal["families"][0]] * 2}),
        "bad_queries_float.json": json.dumps({"families": [{"name": "vf_t0", "queries": 1e300}]}),
        "bad_queries_negative.json": json.dumps({"families": [{"name": "vf_t0", "queries": -1}]}),
        "bad_queries_wrong.json": json.dumps({"families": [{"name": "vf_t0", "queries": 3}]}),
        "bad_collisions_wrong.json": json.dumps(
            {"families": [{"name": "vf_t0", "queries": 2, "collisions": 2}]}),
        "bad_generator_number.json": json.dumps({"generator": 7, "families": minimal["families"]}),
        "bad_scale_string.json": json.dumps(
            {"families": [dict(minimal["families"][0], scale="big")]}),
        "bad_family_not_object.json": json.dumps({"families": ["vf_t0"]}),
    }
    for name, text in bad.items():
        write("suite_manifest", name, text)


if __name__ == "__main__":
    main()
