# The share of each storey's floor from which some wall of the viewer's cell draws its
# neighbour as geometry: floor points on a 0.25 m grid inside each cell, tested against the
# geometry zones of that cell's walls in `cavewall plan --json` output.
# Usage: python3 geometry_share.py PLAN.json SCENE.json
import json, collections, sys
p=json.load(open(sys.argv[1])); s=json.load(open(sys.argv[2]))
cells=s['cells']
def inside(poly, x, z):
    sign=0
    for i in range(len(poly)):
        ax,az=poly[i]; bx,bz=poly[(i+1)%len(poly)]
        c=(bx-ax)*(z-az)-(bz-az)*(x-ax)
        if abs(c)<1e-12: continue
        sg=1 if c>0 else -1
        if sign==0: sign=sg
        elif sg!=sign: return False
    return True
geo=collections.defaultdict(list)
for zn in p['zones']:
    if zn['kind']=='geometry': geo[zn['cell']].append(zn['floorPolygon'])
step=0.25; tot=collections.Counter(); g=collections.Counter()
for ci,c in enumerate(cells):
    reg=c['region']; xs=[q[0] for q in reg]; zs=[q[1] for q in reg]; st=c['name'].split('/')[0]
    x=min(xs)+step/2
    while x<max(xs):
        zz=min(zs)+step/2
        while zz<max(zs):
            if inside(reg,x,zz):
                tot[st]+=1
                if any(inside(poly,x,zz) for poly in geo.get(ci,[])): g[st]+=1
            zz+=step
        x+=step
print(' '.join('storey %s: %.1f %%' % (k, 100*g[k]/tot[k]) for k in sorted(tot)), 'all: %.1f %%' % (100*sum(g.values())/sum(tot.values())))
