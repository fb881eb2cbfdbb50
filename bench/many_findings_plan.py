# SPDX-License-Identifier: GPL-3.0-or-later
# Writes a plan with N wall_overlap findings: N walls, each drawn again 5 cm off its line.
# Usage: python3 bench/many_findings_plan.py N OUT.json
import sys, json
n=int(sys.argv[1]); out=sys.argv[2]
walls=[]
for k in range(n):
    x=(k%50)*3.0; y=(k//50)*2.0
    walls.append({"id":"a%d"%k,"from":[x,y],"to":[x+2,y],"thickness":0.2})
    walls.append({"id":"b%d"%k,"from":[x,y+0.05],"to":[x+2,y+0.05],"thickness":0.2})
side=max(150, 2*(n//50+2))
json.dump({"format":"roomcad-plan","version":1,"units":"m","site":{"origin":[-2,-2],"cells":[160,side],"cell_size":1,"max_height":4},"walls":walls,"openings":[]},open(out,'w'))
