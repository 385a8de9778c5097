#!/usr/bin/env python3
"""The core's modules depend on each other one way only (docs/core_modules.md).

Reads the modules, in their order from the bottom up, and the public headers
each owns from the table in docs/core_modules.md, then checks every file
under core/src/<module>/ and every public header: an include of a public
header or of another module's private header ("fog/volume_geometry.hpp")
must name a module below (or the same one, for public headers); a plain
private include must name a file in the module's own folder. Every public
header must have an owner.
Usage: check_core_modules.py <repository root>
"""
import os
import re
import sys

root = sys.argv[1]
doc = open(os.path.join(root, 'docs/core_modules.md')).read()
order, owner = [], {}
for row in re.findall(r'^\| `(\w+)` \|[^|]*\|([^|]*)\|', doc, re.M):
    order.append(row[0])
    for header in re.findall(r'`([\w/]+\.hpp)`', row[1]):
        owner['aerial/' + header] = row[0]
core = os.path.join(root, 'core')
problems = []
public = set()
for folder, _, files in os.walk(os.path.join(core, 'include/aerial')):
    for name in files:
        public.add(os.path.relpath(os.path.join(folder, name), os.path.join(core, 'include')))
problems += [f'{h}: no module owns it (docs/core_modules.md)' for h in sorted(public - set(owner))]


def check(path, module, private_dir):
    text = open(path).read()
    rank = order.index(module)
    for inc in re.findall(r'#include <(aerial/[^>]+)>', text):
        if inc in owner and order.index(owner[inc]) > rank:
            problems.append(f'{path}: {inc} belongs to {owner[inc]}, above {module}')
    if private_dir is None:
        return
    for inc in re.findall(r'#include "([^"]+)"', text):
        if '/' in inc:
            other = inc.split('/')[0]
            if other not in order or order.index(other) >= rank:
                problems.append(f'{path}: "{inc}" is not a module below {module}')
        elif not os.path.exists(os.path.join(private_dir, inc)):
            problems.append(f'{path}: "{inc}" is not in {module}\'s folder')


for header in sorted(public & set(owner)):
    check(os.path.join(core, 'include', header), owner[header], None)
for module in order:
    folder = os.path.join(core, 'src', module)
    if not os.path.isdir(folder):
        problems.append(f'{folder}: missing')
        continue
    for name in sorted(os.listdir(folder)):
        check(os.path.join(folder, name), module, folder)
stray = [n for n in os.listdir(os.path.join(core, 'src')) if n not in order]
problems += [f'core/src/{n}: not in a module folder' for n in stray]
if problems:
    print('\n'.join(problems))
    sys.exit(1)
print(f'core modules: {" <- ".join(order)}; {len(owner)} public headers owned, one way only')
