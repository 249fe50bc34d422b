#!/usr/bin/env python3
"""Medians and ratios of Experiments 4 and 6 from one genmod_procedural_bench JSON run.

Usage: experiment_ratios.py exp.json   (a run with --benchmark_repetitions and
--benchmark_out_format=json; see bench/procedural/human_tree_bench.cpp)."""
import json
import sys


def main(path):
    with open(path) as f:
        data = json.load(f)
    median, counters = {}, {}
    for b in data["benchmarks"]:
        name = b.get("run_name", b["name"])
        if b.get("aggregate_name") == "median" or ("aggregate_name" not in b and name not in median):
            median[name] = b["cpu_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
        if "aggregate_name" not in b or b.get("aggregate_name") == "median":
            counters[name] = {k: v for k, v in b.items() if isinstance(v, (int, float)) and k not in (
                "cpu_time", "real_time", "iterations", "repetitions", "repetition_index", "threads",
                "per_family_instance_index", "family_index")}
    print("CPU time medians (ms):")
    for name, t in median.items():
        extra = ", ".join(f"{k} {v:g}" for k, v in sorted(counters.get(name, {}).items()))
        print(f"  {name:40s} {t:10.3f}   {extra}")
    print("\nExperiment 4 (polygon counts):")
    legs = [(int(n.split(":")[1]), counters[n]["faces"]) for n in median if n.startswith("BM_Exp4_Luggage/")]
    for i, (k, faces) in enumerate(legs):
        step = "" if i == 0 else f"  (+{faces - legs[i - 1][1]:.0f} for 6 legs, {(faces - legs[i - 1][1]) / 6:.0f} per leg)"
        print(f"  luggage {k:2d} legs: {faces:.0f} faces{step}")
    for n in median:
        if n.startswith("BM_Exp4_Tree/"):
            c = counters[n]
            print(f"  tree level {n.split(':')[1]}: {c['faces']:.0f} faces, {c['branches']:.0f} branches")
    print("\nExperiment 6 (ratio cache / off, CPU medians of this run; thesis in brackets):")
    pairs = [
        ("Luggage 30 legs cold", "BM_LuggageCacheCold/30", "BM_LuggageCacheOff/30", "0.53"),
        ("Luggage 30 legs warm, a luggage hit (issue 12: <= 0.1)", "BM_LuggageCacheWarm/30", "BM_LuggageCacheOff/30", "-"),
        ("Luggage 30 legs parts cached cold", "BM_LuggagePartsCachedCold/30", "BM_LuggageCacheOff/30", "0.53"),
        ("Luggage 30 legs parts cached warm (claim 13: <= 0.6)", "BM_LuggagePartsCachedWarm/30", "BM_LuggageCacheOff/30",
         "0.48-0.50"),
        ("Tree L6 whole tree cold", "BM_TreeCacheCold", "BM_TreeCacheOff", "1.20-1.24"),
        ("Tree L6 whole tree warm (claim 13: <= 0.3)", "BM_TreeCacheWarm", "BM_TreeCacheOff", "0.20"),
        ("Tree L6 branches only cold", "BM_TreeBranchesCachedCold", "BM_TreeCacheOff", "0.94-0.95"),
        ("Tree L6 branches only warm", "BM_TreeBranchesCachedWarm", "BM_TreeCacheOff", "0.95-0.96"),
        ("Human feet only cold (claim 14: 0.9-1.1, <= 1.25)", "BM_HumanFeetCachedCold", "BM_HumanCacheOff", "0.99-1.02"),
        ("Human feet only warm (claim 14: 0.9-1.1)", "BM_HumanFeetCachedWarm", "BM_HumanCacheOff", "0.98-1.00"),
        ("Human legs cached warm", "BM_HumanLegsCachedWarm", "BM_HumanCacheOff", "-"),
    ]
    for label, a, b, thesis in pairs:
        if a in median and b in median:
            print(f"  {label:52s} {median[a] / median[b]:6.3f}  [{thesis}]")
    print("\nCold penalty of a cacheable call (its miss: key, lookup, store / the same call uncached; issue 12: < 1.05):")
    penalties = [
        ("Luggage, call (cold / parts cached cold; a copy)", "BM_LuggageCacheCold/30", "BM_LuggagePartsCachedCold/30"),
        ("Luggage, call_shared (cold / parts cached cold)", "BM_LuggageSharedCacheCold/30",
         "BM_LuggageSharedPartsCachedCold/30"),
        ("Luggage's leg (leg cold / leg off)", "BM_LuggageLegCold", "BM_LuggageLegAlone"),
        ("Synthetic leg (cache_bench)", "BM_LegCold", "BM_LegOff"),
    ]
    for label, a, b in penalties:
        if a in median and b in median:
            print(f"  {label:52s} {median[a] / median[b]:6.3f}")


if __name__ == "__main__":
    main(sys.argv[1])
