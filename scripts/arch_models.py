# Writes the architectural test models tests/data/arch/rooms_door_window.json (two rooms,
# a door and a window in their common wall) and floor_court.json (a floor around a court):
# string ids, points, no weights. Usage: python3 scripts/arch_models.py tests/data/arch
import json, sys
def model(faces, rooms, dim):
    verts=[]; edges=[]; regions=[]; inc=[]
    def v(p):
        if p not in verts: verts.append(p)
        return "v%d"%verts.index(p)
    def e(a,b):
        k=tuple(sorted([a,b]))
        if k not in edges: edges.append(k)
        return "e%d"%edges.index(k)
    face_inc=[]
    for name,labels,loops in faces:
        for loop in loops:
            for i in range(len(loop)):
                a=loop[i]; b=loop[(i+1)%len(loop)]
                v(a); v(b)
                face_inc.append((name, e(a,b)))
    for i,p in enumerate(verts):
        regions.append({"id":"v%d"%i,"dim":0,"point":list(p)})
    for i,(a,b) in enumerate(edges):
        regions.append({"id":"e%d"%i,"dim":1})
        inc.append({"from":"e%d"%i,"to":v(a)}); inc.append({"from":"e%d"%i,"to":v(b)})
    for name,labels,loops in faces:
        r={"id":name,"dim":2}
        if labels: r["labels"]=labels
        regions.append(r)
    for f,ed in face_inc: inc.append({"from":f,"to":ed})
    for name,labels,fs in rooms:
        r={"id":name,"dim":3}
        if labels: r["labels"]=labels
        regions.append(r)
        for f in fs: inc.append({"from":name,"to":f})
    return {"dimension":dim,"regions":regions,"incidence":inc}
def dump(m, path):
    lines=['{"dimension": %d,'%m["dimension"], ' "regions": [']
    lines.append('  '+',\n  '.join(json.dumps(r) for r in m["regions"])+'],')
    lines.append(' "incidence": [')
    lines.append('  '+',\n  '.join(json.dumps(r) for r in m["incidence"])+']}')
    open(path,'w').write('\n'.join(lines)+'\n')

def box_faces(x0,x1,tag,split_x=None):
    pass
X=[0,4,8]; Y=6; Z=3
door=[(4,1,0),(4,2,0),(4,2,2),(4,1,2)]
win=[(4,3,1),(4,5,1),(4,5,2),(4,3,2)]
faces=[]
for k,(a,b) in enumerate([(0,4),(4,8)],1):
    fl=[(a,0,0),(b,0,0)]
    if b==4: fl+= [(4,1,0),(4,2,0)]
    fl+=[(b,Y,0),(a,Y,0)]
    if a==4: fl+=[(4,2,0),(4,1,0)]
    faces.append(("floor %d"%k,{"kind":"floor"},[fl]))
    faces.append(("ceiling %d"%k,{"kind":"ceiling"},[[(a,0,Z),(b,0,Z),(b,Y,Z),(a,Y,Z)]]))
    faces.append(("south %d"%k,{"kind":"wall"},[[(a,0,0),(b,0,0),(b,0,Z),(a,0,Z)]]))
    faces.append(("north %d"%k,{"kind":"wall"},[[(a,Y,0),(b,Y,0),(b,Y,Z),(a,Y,Z)]]))
    xo = a if k==1 else b
    faces.append(("%s wall"%("west" if k==1 else "east"),{"kind":"wall"},[[(xo,0,0),(xo,Y,0),(xo,Y,Z),(xo,0,Z)]]))
faces.append(("wall",{"kind":"wall"},[[(4,0,0),(4,1,0),(4,1,2),(4,2,2),(4,2,0),(4,Y,0),(4,Y,Z),(4,0,Z)], win]))
faces.append(("door",{"kind":"door"},[door]))
faces.append(("window",{"kind":"window"},[win]))
common=["wall","door","window"]
rooms=[("room 1",{"name":"kitchen"},["floor 1","ceiling 1","south 1","north 1","west wall"]+common),
       ("room 2",{"name":"living"},["floor 2","ceiling 2","south 2","north 2","east wall"]+common)]
m=model(faces,rooms,3)
dump(m, sys.argv[1]+"/rooms_door_window.json")
# floor with a court: annulus 2-region
court=[(3,3,0),(5,3,0),(5,5,0),(3,5,0)]
m2=model([("floor",{"name":"ground floor"},[[(0,0,0),(8,0,0),(8,8,0),(0,8,0)],court])],[],2)
dump(m2, sys.argv[1]+"/floor_court.json")
