#!/usr/bin/env python3
"""Fills unfinished messages of a Qt .ts file from translations already made elsewhere.

    scripts/ts_fill.py translations/needlebench_de.ts --from OLD.ts [--tsv FILE.tsv ...]

--from: an earlier .ts (e.g. from git: strings that moved to another context keep their
translation when the source text is the same). --tsv: lines `context<TAB>source<TAB>translation`
(context may be empty to match any). Prints what it could not fill; exits 0.
"""
import argparse
import sys
import xml.etree.ElementTree as ET


def messages(root):
    for ctx in root.iter('context'):
        name = ctx.findtext('name') or ''
        for m in ctx.iter('message'):
            yield name, m


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('target')
    ap.add_argument('--from', dest='sources', action='append', default=[])
    ap.add_argument('--tsv', action='append', default=[])
    ap.add_argument('--override', action='store_true',
                    help='also replace finished translations with the --tsv ones (same context and source)')
    args = ap.parse_args()

    by_ctx, by_src = {}, {}
    for path in args.sources:
        for ctx, m in messages(ET.parse(path).getroot()):
            t = m.find('translation')
            if t is None or t.get('type') in ('unfinished', 'vanished', 'obsolete') and not (t.text or list(t)):
                continue
            src = m.findtext('source')
            forms = [n.text for n in t.findall('numerusform')]
            value = forms if forms else t.text
            if not value:
                continue
            by_ctx[(ctx, src)] = value
            by_src.setdefault(src, value)
    tsv_keys = {}
    for path in args.tsv:
        with open(path, encoding='utf-8') as f:
            for line in f:
                line = line.rstrip('\n')
                if not line.strip():
                    continue
                parts = line.split('\t')
                if len(parts) != 3:
                    print(f'{path}: skipped malformed line: {line[:80]}', file=sys.stderr)
                    continue
                ctx, src, tr = (p.replace('\\n', '\n') for p in parts)
                if ctx:
                    by_ctx[(ctx, src)] = tr
                    tsv_keys[(ctx, src)] = tr
                by_src[src] = tr
                by_src.setdefault(src.strip(), tr)

    tree = ET.parse(args.target)
    missing = 0
    for ctx, m in messages(tree.getroot()):
        t = m.find('translation')
        src = m.findtext('source')
        if t is not None and args.override and t.get('type') is None and m.get('numerus') != 'yes' \
                and (ctx, src) in tsv_keys and t.text != tsv_keys[(ctx, src)]:
            t.text = tsv_keys[(ctx, src)]
            continue
        if t is None or t.get('type') != 'unfinished':
            continue
        value = by_ctx.get((ctx, src), by_src.get(src))
        if value is None and src:
            # A text that differs only in its surrounding white space (a trailing newline).
            base = by_src.get(src.strip())
            if isinstance(base, str):
                lead = src[:len(src) - len(src.lstrip())]
                trail = src[len(src.rstrip()):]
                value = lead + base.strip() + trail
        if value is None:
            missing += 1
            print(f'untranslated: [{ctx}] {src!r}')
            continue
        if m.get('numerus') == 'yes':
            forms = value if isinstance(value, list) else [value, value]
            for n in list(t):
                t.remove(n)
            for form in forms:
                ET.SubElement(t, 'numerusform').text = form
        else:
            t.text = value[0] if isinstance(value, list) else value
        t.attrib.pop('type', None)
    tree.write(args.target, encoding='utf-8', xml_declaration=True)
    print(f'{missing} message(s) left untranslated')


if __name__ == '__main__':
    main()
