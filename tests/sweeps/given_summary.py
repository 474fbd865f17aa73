"""Sums up given_run.py's mismatch files: python3 given_summary.py FILE... (counts by kind, one example each)."""
import json,collections,sys
c=collections.Counter(); ex={}
for f in sys.argv[1:]:
  for l in open(f):
    o=json.loads(l)
    if 'panic' in o: print('PANIC', o['files'][:3], o['panic'][-300:]); continue
    if 'cat' not in o: continue
    cat=o['cat']
    if cat=='value-differs' and isinstance((o['num'] or {}).get('value'),str): cat='num-subs-unevaluated'
    m=''
    if cat=='sym-refuses': m=(o['sym'] or {}).get('error',{}).get('message','')
    if cat=='sym-answers-num-refuses': m=(o['num'] or {}).get('error',{}).get('message','')
    import re; m=re.sub(r'X\d+','X',m)[:90]
    k=(cat,o['kind'],m); c[k]+=1; ex.setdefault(k,o)
for k,v in c.most_common():
  print(v,k); o=ex[k]; print('     ',o['file'],o['x'],o['expr'][:160])
