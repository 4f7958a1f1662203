#!/usr/bin/env python3
# Interleaves programs built from visibility_times.cpp (one per commit or variant) and
# prints, per map, the best and the median µs/query and their ratio to the first program.
#   compare.py ./times_before,./times_now ROUNDS MAP...
# Rounds alternate the order of the programs, so a change of load hits all alike.
import subprocess, statistics, collections, sys
bins = sys.argv[1].split(','); rounds = int(sys.argv[2]); maps = sys.argv[3:]
res = {b: collections.defaultdict(list) for b in bins}; chk = {b: {} for b in bins}
for r in range(rounds):
    for b in (bins if r % 2 == 0 else bins[::-1]):
        out = subprocess.run([b, 'time'] + maps, capture_output=True, text=True).stdout
        for line in out.split('\n'):
            if not line: continue
            n, t, s = line.split(); res[b][n].append(float(t)); chk[b][n] = s
print(f"{'map':18s} " + " | ".join(bins) + "   (min, median µs; ratio to the first)")
for n in maps:
    bm, bd = min(res[bins[0]][n]), statistics.median(res[bins[0]][n])
    line = f"{n:18s} {bm:7.3f} {bd:7.3f}"
    for b in bins[1:]:
        m, d = min(res[b][n]), statistics.median(res[b][n])
        line += f" | {m:7.3f} {d:7.3f} ({m/bm:.2f} {d/bd:.2f})"
    print(line, " checksums", " ".join(chk[b][n] for b in bins))
