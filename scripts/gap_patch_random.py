#!/usr/bin/env python3
"""Where a force run across an end-post gap bears at P1 and P2: seeded random
scenes (gap 0.5-10 mm, cuts 30-90 deg, y_w across the head, level rail
(beta 1e-4), a linear dip of beta 0.005-0.05 or a cosine dip of beta
0.01-0.05 over 0.05-0.3 m, 20-80 m/s, the lumped and the
discrete track, the flat head under a thin disc or 60E1 under a 1:40 cone),
each also with the gap closed (joint.gap 0). For each bearing rail end (over
1 % of the force) its touching point's distance d from its own cut's edge
over its patch semi-length a (JSON hertz_at_p1 / hertz_at_p2 .rail_ends
.cut_edge_distance_semi_lengths) and its law; counts of runs whose P1
(> 1.01 P0) or P2 is borne with d < a or on an edge, and the runs' verdicts.
Usage: /usr/bin/python3 scripts/gap_patch_random.py BUILD/scenes/railjoint [count] [seeds] [--rows]"""
import json
import random
import subprocess
import sys

SCENES = {"lumped": "scenes/forces/lumped_track.toml", "discrete": "scenes/forces/discrete_track.toml"}


def scene(rng):
    track = rng.choice(["lumped", "discrete"])
    keys = [f"joint.gap={rng.uniform(0.5e-3, 10e-3):.5f}", f"joint.theta_deg={rng.uniform(30, 90):.2f}",
            f"wheel.speed={rng.uniform(20, 80):.1f}"]
    kind = rng.random()
    if kind < 1 / 3:
        # Level rail but for the gap (a joint needs some dip: beta 1e-4 rad
        # lowers the outgoing rail 1e-4 of the way, a micrometre in 10 mm).
        keys.append("joint.beta=0.0001")
        dip = "none"
    elif kind < 2 / 3:
        beta = rng.uniform(0.005, 0.05)
        keys.append(f"joint.beta={beta:.4f}")
        dip = f"linear {beta:.3f}"
    else:
        beta = rng.uniform(0.01, 0.05)
        length = rng.uniform(0.05, 0.3)
        keys += [f"joint.beta={beta:.4f}", "joint.dip_shape=cosine", f"joint.dip_length={length:.3f}"]
        dip = f"cos {beta:.3f}/{length:.2f}"
    if rng.random() < 0.5:
        keys += ["joint.rail_profile=60E1", "joint.half_width=0.036", "wheel.conicity=0.025", "wheel.width=0.07",
                 f"wheel.y={rng.uniform(-0.012, 0.012):.4f}"]
        head = "60E1"
    else:
        keys.append(f"wheel.y={rng.uniform(-0.015, 0.015):.4f}")
        head = "flat"
    return track, keys, dip, head


def run(binary, track, keys):
    args = [binary, "simulate", SCENES[track], "--json"]
    for k in keys:
        args += ["--set", k]
    out = subprocess.run(args, capture_output=True, text=True)
    try:
        sim = json.loads(out.stdout)["sim"]
    except (json.JSONDecodeError, KeyError):
        raise RuntimeError(" ".join(args) + f"\nrc {out.returncode}\n" + out.stderr[-2000:])
    return sim, out.returncode


def bearing(h):
    """The rail ends bearing over 1 % of the force: (rail, share, d/a, law, at edge)."""
    if not h or not h.get("rail_ends"):
        return []
    total = sum(e["normal_force_N"] for e in h["rail_ends"])
    out = []
    for e in h["rail_ends"]:
        if e["normal_force_N"] > 0.01 * total:
            d = e["cut_edge_distance_semi_lengths"]
            out.append((e["rail"], e["normal_force_N"] / total, float("inf") if d is None else d, e["law"],
                        e["at_cut_edge"]))
    return out


def cut(ends):
    return any(d < 1.0 for _, _, d, _, _ in ends)


def edge(ends):
    return any(at for *_, at in ends)


def fmt(ends):
    return " ".join(f"r{r} {100 * s:.0f}% d/a {d:.2f} {law[:4]}{' EDGE' if at else ''}" for r, s, d, law, at in ends)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    rows = "--rows" in sys.argv
    binary = args[0]
    count = int(args[1]) if len(args) > 1 else 20
    seeds = [int(s) for s in args[2].split(",")] if len(args) > 2 else [1, 2]
    table = []
    for seed in seeds:
        rng = random.Random(seed)
        for gap_open in (True, False):
            rng = random.Random(seed)
            n = dyn = p1_cut = p1_edge = p2_cut = p2_edge = other = gap_suspect = gap_only = 0
            d_p1 = []
            for i in range(count):
                track, keys, dip, head = scene(rng)
                if not gap_open:
                    keys = ["joint.gap=0" if k.startswith("joint.gap=") else k for k in keys]
                sim, rc = run(binary, track, keys)
                f = sim["forces"]
                p1, p0 = f["p1_N"], f["static_N"] if "static_N" in f else f["p0_N"]
                e1, e2 = bearing(f.get("hertz_at_p1")), bearing(f.get("hertz_at_p2"))
                n += 1
                is_dyn = p1 > 1.01 * p0
                dyn += is_dyn
                p1_cut += is_dyn and cut(e1)
                p1_edge += is_dyn and edge(e1)
                p2_cut += cut(e2)
                p2_edge += edge(e2)
                if is_dyn:
                    d_p1 += [d for _, _, d, _, _ in e1]
                reasons = [r for r in sim["verdict_reason"].split("; ") if r]
                gap_reason = any(" end-post gap by rail end " in r for r in reasons)
                other_reason = any(" end-post gap by rail end " not in r for r in reasons)
                other += other_reason
                gap_suspect += gap_reason
                gap_only += gap_reason and not other_reason
                if rows:
                    print(f"seed {seed} {'gap' if gap_open else 'closed'} #{i} {track} {head} {dip} "
                          f"{' '.join(keys)}: P1/P0 {p1 / p0:.3f} P1[{fmt(e1)}] P2[{fmt(e2)}] rc {rc} "
                          f"{sim['verdict']}{' (end-post gap)' if gap_reason else ''}: {sim['verdict_reason'][:160]}", flush=True)
            table.append((seed, "open (0.5-10 mm)" if gap_open else "closed (0)", n, dyn, p1_cut, p1_edge, p2_cut,
                          p2_edge, other, gap_suspect, gap_only, sorted(d_p1)))
    print("| seed | gap | runs | P1 > 1.01 P0 | of them P1 borne with d < a | P1 on a cut edge | "
          "P2 borne with d < a | P2 on a cut edge | suspect for other reasons | suspect: end-post gap | "
          "of them for that alone |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for seed, gap, n, dyn, c1, g1, c2, g2, oth, gsus, gonly, _ in table:
        print(f"| {seed} | {gap} | {n} | {dyn} | {c1} | {g1} | {c2} | {g2} | {oth} | {gsus} | {gonly} |")
    for seed, gap, *_, d in table:
        if d:
            fin = [x for x in d if x != float("inf")]
            print(f"seed {seed} {gap}: d/a of the rail ends bearing at a dynamic P1: min {min(fin) + 0.0:.2f}, "
                  f"median {d[len(d) // 2]:.2f}, {sum(x < 1 for x in d)} of {len(d)} under 1")


if __name__ == "__main__":
    main()
