#!/usr/bin/python3
"""SHA-256 of every computed dataset in a planarbench results file, with h5py alone.

Independent of planarbench's own reader: it opens the file with h5py and numpy
only, so a hash that matches proves the file is complete and readable without
the code under test.

A run's hash covers, for each dataset under /runs/<case>/<engine>/ in sorted
path order (bodies/<body>/{angle, angular_velocity, position, time, velocity},
contacts, events): its path relative to the run, its element type, its shape
and its values' bytes (decompressed, little-endian as stored; a string column
of a campaign: each string's UTF-8 bytes and its length). `datasets` and
`same` also cover every dataset under /campaign (a campaign's or a sweep's
table of runs). Attributes are not hashed: wall_time_s and /parameters (time, host, compiler) legitimately
change from run to run, and everything computed is in the datasets.

Usage (exit 0 ok, 1 mismatch or unreadable file, 2 bad usage):
  dataset_hashes.py runs FILE            JSON {case: {engine: sha256}} on stdout
  dataset_hashes.py datasets FILE        JSON {/runs/<case>/<engine>/<dataset>: sha256}
  dataset_hashes.py same A B             A and B hold the same datasets, bit for bit
  dataset_hashes.py compare PINNED FILE  FILE's run hashes equal those pinned in PINNED
  dataset_hashes.py bless PINNED FILE    rewrites PINNED's hashes from FILE (keeps its args)
"""
import hashlib
import json
import sys

import h5py
import numpy as np

BLESS_HINT = ("If the change is intended (a solver, adapter, case file or dependency changed "
              "on purpose), re-bless from the repository root with a Release build:\n"
              "    bash scripts/bless_hashes.sh [BUILD_DIR]      (default build/release)\n"
              "then review and commit tests/data/determinism/hashes.json. "
              "See tests/durability/README.md.")


def type_text(dtype):
    """A canonical text of an element type, independent of numpy's repr."""
    if dtype.names is None:
        return f"{dtype.base.str}{list(dtype.shape)}"
    return "{" + ";".join(f"{n}:{type_text(dtype.fields[n][0])}" for n in dtype.names) + "}"


def dataset_digest(relative_path, dataset):
    """SHA-256 over one dataset's path, type, shape and value bytes."""
    values = np.ascontiguousarray(dataset[()])
    h = hashlib.sha256()
    h.update(relative_path.encode("utf-8") + b"\0")
    vlen = values.dtype.kind == "O"  # variable-length strings: the bytes, not the pointers
    h.update((b"vlen-str" if vlen else type_text(values.dtype).encode("ascii")) + b"\0")
    h.update(repr(tuple(int(n) for n in values.shape)).encode("ascii") + b"\0")
    if vlen:
        for v in values.ravel():
            b = v if isinstance(v, bytes) else str(v).encode("utf-8")
            h.update(len(b).to_bytes(8, "little") + b)
    else:
        h.update(values.tobytes())
    return h


def run_datasets(run):
    """Sorted (relative path, dataset) of every dataset under one run group."""
    found = []
    run.visititems(lambda name, obj: found.append((name, obj))
                   if isinstance(obj, h5py.Dataset) else None)
    return sorted(found, key=lambda item: item[0])


def run_groups(f):
    """(case, engine, group) of every run in the file, cases and engines sorted."""
    if "runs" not in f:
        raise KeyError("/runs is missing (not a planarbench results file)")
    for case in sorted(f["runs"]):
        for engine in sorted(f["runs"][case]):
            yield case, engine, f["runs"][case][engine]


def run_hashes(path):
    """{case: {engine: sha256 hex}}, one digest over all of a run's datasets."""
    out = {}
    with h5py.File(path, "r") as f:
        for case, engine, run in run_groups(f):
            h = hashlib.sha256()
            for name, d in run_datasets(run):
                h.update(dataset_digest(name, d).digest())
            out.setdefault(case, {})[engine] = h.hexdigest()
    return out


def dataset_hashes(path):
    """{dataset path: sha256 hex} of every dataset of every run, and of /campaign."""
    out = {}
    with h5py.File(path, "r") as f:
        for _, _, run in run_groups(f):
            for name, d in run_datasets(run):
                out[f"{run.name}/{name}"] = dataset_digest(name, d).hexdigest()
        if "campaign" in f:
            for name, d in run_datasets(f["campaign"]):
                out[f"/campaign/{name}"] = dataset_digest(name, d).hexdigest()
    return out


def command_args(path):
    """The file's /parameters command_line without the program and --out value."""
    with h5py.File(path, "r") as f:
        words = str(f["parameters"].attrs.get("command_line", "")).split()
    args, skip = [], True  # the first word is the program
    for w in words:
        if skip:
            skip = False
        elif w == "--out":
            skip = True
        elif not w.startswith("--out="):
            args.append(w)
    return " ".join(args)


def same(a, b):
    da, db = dataset_hashes(a), dataset_hashes(b)
    only = sorted(set(da) ^ set(db))
    changed = sorted(n for n in set(da) & set(db) if da[n] != db[n])
    for n in only:
        print(f"only in {'the first' if n in da else 'the second'} file: {n}")
    for n in changed:
        print(f"differs: {n}")
    if only or changed:
        print(f"{len(changed)} of {len(da)} datasets differ, {len(only)} present in one file only")
        return 1
    print(f"{len(da)} datasets identical")
    return 0


def compare(pinned_path, path):
    with open(pinned_path, encoding="utf-8") as fp:
        pinned = json.load(fp)
    want, got = pinned["hashes"], run_hashes(path)
    problems = []
    for case in sorted(set(want) | set(got)):
        w, g = want.get(case, {}), got.get(case, {})
        for engine in sorted(set(w) | set(g)):
            if engine not in g:
                problems.append(f"MISSING {case} x {engine}: pinned but not in the results")
            elif engine not in w:
                problems.append(f"NEW     {case} x {engine}: in the results but not pinned "
                                f"(now {g[engine]})")
            elif w[engine] != g[engine]:
                problems.append(f"CHANGED {case} x {engine}: pinned {w[engine][:16]}, "
                                f"now {g[engine][:16]}")
    total = sum(len(v) for v in got.values())
    if problems:
        print(f"{len(problems)} case x engine hashes differ from {pinned_path} "
              f"(command: planarbench {pinned['args']}):")
        for p in problems:
            print("  " + p)
        print(BLESS_HINT)
        return 1
    print(f"{total} case x engine hashes match {pinned_path}")
    return 0


def bless(pinned_path, path):
    with open(pinned_path, encoding="utf-8") as fp:
        pinned = json.load(fp)
    args = command_args(path)
    if args != pinned["args"]:
        print(f"{path} was made by 'planarbench {args}', not by the pinned "
              f"'planarbench {pinned['args']}'", file=sys.stderr)
        return 1
    old = pinned.get("hashes", {})
    pinned["hashes"] = run_hashes(path)
    with open(pinned_path, "w", encoding="utf-8") as fp:
        json.dump(pinned, fp, indent=2, sort_keys=False)
        fp.write("\n")
    changed = [f"{c} x {e}" for c, engines in pinned["hashes"].items() for e, h in engines.items()
               if old.get(c, {}).get(e) != h]
    print(f"wrote {pinned_path}: {sum(len(v) for v in pinned['hashes'].values())} hashes, "
          f"{len(changed)} changed" + (f" ({', '.join(changed)})" if changed else ""))
    return 0


def main(argv):
    commands = {"runs": 1, "datasets": 1, "same": 2, "compare": 2, "bless": 2}
    if len(argv) < 2 or argv[1] not in commands or len(argv) != 2 + commands[argv[1]]:
        print(__doc__, file=sys.stderr)
        return 2
    cmd, files = argv[1], argv[2:]
    try:
        if cmd == "runs":
            print(json.dumps(run_hashes(files[0]), indent=2))
            return 0
        if cmd == "datasets":
            print(json.dumps(dataset_hashes(files[0]), indent=2))
            return 0
        return {"same": same, "compare": compare, "bless": bless}[cmd](*files)
    except (OSError, KeyError) as e:
        print(f"cannot read results: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
