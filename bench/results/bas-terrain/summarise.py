import csv,glob,statistics,sys,os
# Summarises the CSVs of run.sh: python3 summarise.py DIR
d=sys.argv[1]
dems=['alps_tiny.asc','alps_small.asc','alps_medium.asc','DEM-kootenai_37x50_1x1.asc','west_bijou_gully.asc']
print('| DEM | planner | init | success | median ratio | worst ratio | improved on the start (best iteration > 0) | median best iteration | median time (s) |')
print('|---|---|---|---:|---:|---:|---:|---:|---:|')
tot={}
for dem in dems:
  for init in ['seeded','paper']:
    f=os.path.join(d,f'{dem}.{init}.csv')
    rows=list(csv.DictReader(open(f)))
    for p in ['bas','lfs-bas','aco-bas','sio-bas','multi-bas']:
      r=[x for x in rows if x['planner']==p]
      ok=[x for x in r if x['success']=='true']
      rat=[float(x['ratio']) for x in ok if x['ratio']]
      bi=[int(x['best_iteration']) for x in ok if x['best_iteration']]
      imp=sum(1 for b in bi if b>0)
      t=[float(x['wall_seconds']) for x in r if x['wall_seconds']]
      fmt=lambda v:'%.4f'%v
      k=(p,init); a=tot.setdefault(k,[0,0,0,0,[]]); a[0]+=len(r); a[1]+=len(ok); a[2]+=imp; a[3]+=len(bi); a[4]+=rat
      print(f"| {dem} | {p} | {init} | {len(ok)}/{len(r)} | {fmt(statistics.median(rat)) if rat else '–'} | {fmt(max(rat)) if rat else '–'} | {imp}/{len(ok)} | {statistics.median(bi) if bi else '–'} | {('%.3f'%statistics.median(t)) if t else '–'} |")
print()
print('| planner | init | success | median ratio | worst ratio | improved on the start |')
print('|---|---|---:|---:|---:|---:|')
for (p,init),a in sorted(tot.items(), key=lambda kv:(kv[0][1]!='seeded',kv[0][0])):
  print(f"| {p} | {init} | {a[1]}/{a[0]} | {'%.4f'%statistics.median(a[4]) if a[4] else '–'} | {'%.4f'%max(a[4]) if a[4] else '–'} | {a[2]}/{a[1]} |")
# sio vs multi
print()
for dem in dems:
  for init in ['seeded','paper']:
    rows=list(csv.DictReader(open(os.path.join(d,f'{dem}.{init}.csv'))))
    same=0;n=0
    for s in ['1','2','3']:
      a=[x for x in rows if x['planner']=='sio-bas' and x['seed']==s][0]
      b=[x for x in rows if x['planner']=='multi-bas' and x['seed']==s][0]
      n+=1
      if a['fitness']==b['fitness'] and a['length']==b['length']: same+=1
    print(f'SAME {dem} {init} sio==multi in {same}/{n}')
