#!/usr/bin/env python3
# usage: compare_gudhi.py GMAP_BINARY [--runs N] [--lutz DIR] [--cubical DIR] [--only NAME...]
#   e.g. compare_gudhi.py target/release/gmap --lutz tests/data/lutz --cubical target/bench-data
#
# Speed against GUDHI on the same cells, in one sitting, as Markdown tables:
# * every .facets file of the Lutz folder: the whole `gmap homology FILE --json` process
#   (wall clock, reading included; integer homology with torsion) against GUDHI's in-process
#   SimplexTree built from the same facets plus Z/2 persistence (parsing the file untimed);
# * random full cubical sets of 48^3 and 96^3 boxes at densities 0.25, 0.5 and 0.7 (each
#   cube present with that probability; SplitMix64 seeded 1000 k + percent, the files of
#   benches/cubical.rs, written to the --cubical folder when missing): `gmap homology
#   FILE.cub --json` against GUDHI's CubicalComplex on the same cubes (gudhi_cubical_file.py).
# Each side runs N times (default 5), alternating, and the medians are compared, both of the
# wall clock and of the CPU time (user + system of every thread: ours from the child's
# rusage, GUDHI's from this process; on a loaded machine the CPU time is the steadier).
# The ratio is GUDHI / ours (above 1: ours is faster); the geometric means are over the
# Lutz files where GUDHI needs at least 2 ms, over the cubical sets, and over both. The last column
# checks that both sides give the same Betti numbers over Z/2 (ours from Z with torsion).
import math, os, statistics, subprocess, sys, time, json

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gudhi  # noqa: E402
from gudhi_cubical_file import read_bitmap, timed  # noqa: E402

MASK = (1 << 64) - 1


def splitmix64(state):
    state = (state + 0x9E3779B97F4A7C15) & MASK
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return state, z ^ (z >> 31)


def cubical_input(folder, k, percent):
    """The random k^3 set at `percent`%, as benches/cubical.rs writes it."""
    path = os.path.join(folder, f"cubical{k}_{percent}.cub")
    if os.path.exists(path):
        return path
    os.makedirs(folder, exist_ok=True)
    state, lines = 1000 * k + percent, ["; random cubical set", "dimension 3"]
    for z in range(k):
        for y in range(k):
            for x in range(k):
                state, r = splitmix64(state)
                if r % 100 < percent:
                    lines.append(f"({x},{y},{z})")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)
    return path


def ours(gmap, path):
    """Wall and CPU seconds (user + system, every thread) of the whole `gmap homology FILE
    --json` process, and its Z/2 Betti numbers."""
    t0 = time.perf_counter()
    p = subprocess.Popen([gmap, "homology", path, "--json"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    p.returncode = status
    t = (time.perf_counter() - t0, ru.ru_utime + ru.ru_stime)
    if status != 0:
        return t, None
    j = json.loads(out)
    betti, torsion = j["betti"], j["torsion"]
    # over Z/2: b_k plus the even invariant factors of H_k and of H_(k-1)
    even = [sum(1 for q in t if q % 2 == 0) for t in torsion]
    return t, [betti[k] + even[k] + (even[k - 1] if k else 0) for k in range(len(betti))]


def in_process(f):
    """Wall and CPU seconds of `f()` in this process, and its result."""
    t0, c0 = time.perf_counter(), time.process_time()
    r = f()
    return (time.perf_counter() - t0, time.process_time() - c0), r


def gudhi_facets(facets):
    def run():
        st = gudhi.SimplexTree()
        for f in facets:
            st.insert(f)
        st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
        return st.betti_numbers()

    return in_process(run)


def same(a, b):
    if a is None or b is None:
        return False
    n = max(len(a), len(b))
    return list(a) + [0] * (n - len(a)) == list(b) + [0] * (n - len(b))


def measure(runs, gudhi_once, ours_once):
    """Medians of (wall, CPU) seconds of each side over `runs` alternating runs."""
    g, o = [], []
    for _ in range(runs):
        tg, bg = gudhi_once()
        to, bo = ours_once()
        g.append(tg)
        o.append(to)
    med = lambda xs, k: statistics.median(x[k] for x in xs)  # noqa: E731
    return (med(g, 0), med(g, 1)), (med(o, 0), med(o, 1)), bg, bo


def row(g, o):
    """The timing cells of a table row: GUDHI and ours in ms (wall / CPU), the two ratios."""
    return f"{g[0] * 1e3:.1f} / {g[1] * 1e3:.1f} | {o[0] * 1e3:.1f} / {o[1] * 1e3:.1f} | {g[0] / o[0]:.2f} / {g[1] / o[1]:.2f}"


def geomean(pairs):
    """Geometric means and minima of the wall and CPU ratios, as text."""
    if not pairs:
        return "none"
    gm = [math.exp(statistics.mean(math.log(p[k]) for p in pairs)) for k in (0, 1)]
    worst = [min(p[k] for p in pairs) for k in (0, 1)]
    return f"geometric mean GUDHI / ours {gm[0]:.2f} wall, {gm[1]:.2f} CPU; worst {worst[0]:.2f} wall, {worst[1]:.2f} CPU"


def main():
    args = sys.argv[1:]
    gmap, runs, lutz, cub, only = args[0], 5, None, None, None
    i = 1
    while i < len(args):
        if args[i] == "--runs":
            runs, i = int(args[i + 1]), i + 2
        elif args[i] == "--lutz":
            lutz, i = args[i + 1], i + 2
        elif args[i] == "--cubical":
            cub, i = args[i + 1], i + 2
        elif args[i] == "--only":
            only, i = set(args[i + 1 :]), len(args)
        else:
            sys.exit(f"unknown argument {args[i]}")
    print(f"GUDHI {gudhi.__version__}, median of {runs} runs per side, alternating; "
          f"ratio = GUDHI / ours (above 1: ours faster)\n")
    kept, cubical = [], []
    if lutz:
        print("| file | dim | facets | GUDHI ms (wall / CPU) | ours ms (wall / CPU) | GUDHI / ours (wall / CPU) | Z/2 Betti agree |")
        print("|---|---|---|---|---|---|---|")
        for name in sorted(os.listdir(lutz)):
            if not name.endswith(".facets") or (only and name not in only):
                continue
            path = os.path.join(lutz, name)
            facets = [list(map(int, l.split())) for l in open(path) if l.strip() and not l.startswith("#")]
            g, o, bg, bo = measure(runs, lambda: gudhi_facets(facets), lambda: ours(gmap, path))
            dim = max(len(f) for f in facets) - 1
            name = name if g[1] >= 0.002 else f"{name} (GUDHI under 2 ms)"
            print(f"| {name} | {dim} | {len(facets)} | {row(g, o)} | "
                  f"{'yes' if same(bg, bo) else f'NO: {bg} vs {bo}'} |", flush=True)
            if g[1] >= 0.002:
                kept.append((g[0] / o[0], g[1] / o[1]))
        print(f"\nLutz files where GUDHI needs at least 2 ms of CPU: {len(kept)}; {geomean(kept)}\n")
    if cub:
        print("| cubical set | cubes | GUDHI ms (wall / CPU) | ours ms (wall / CPU) | GUDHI / ours (wall / CPU) | Z/2 Betti agree |")
        print("|---|---|---|---|---|---|")
        for k in (48, 96):
            for percent in (25, 50, 70):
                path = cubical_input(cub, k, percent)
                top = read_bitmap(path)
                cubes = int((top == 0).sum())
                g, o, bg, bo = measure(runs, lambda: in_process(lambda: timed(top)[1]), lambda: ours(gmap, path))
                print(f"| {k}³ at 0.{percent} | {cubes} | {row(g, o)} | "
                      f"{'yes' if same(bg, bo) else f'NO: {bg} vs {bo}'} |", flush=True)
                cubical.append((g[0] / o[0], g[1] / o[1]))
        print(f"\ncubical sets: {geomean(cubical)}\n")
    if kept and cubical:
        print(f"all {len(kept) + len(cubical)} rows: {geomean(kept + cubical)}")


if __name__ == "__main__":
    main()
