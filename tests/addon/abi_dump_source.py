"""Writes a C program that prints, as JSON, what the compiler makes of edgelight.h: every
struct's size and field offsets, every EL_ constant and enum value. The field and constant lists
come from the header itself, so the check needs no second hand-written copy of them.

    python3 abi_dump_source.py HEADER OUT.c
"""
import re
import sys


def parse(header):
    text = re.sub(r"/\*.*?\*/", "", open(header, encoding="utf-8").read(), flags=re.S)
    structs = {}
    for body, name in re.findall(r"typedef struct (?:\w+ )?\{(.*?)\}\s*(\w+);", text, flags=re.S):
        fields = []
        for decl in body.split(";"):
            m = re.match(r"\s*(?:const\s+)?[\w\s\*]+?[\s\*](\w+)(\[\d+\])?\s*$", decl.strip() and decl)
            if m:
                fields.append(m.group(1))
        structs[name] = fields
    constants = re.findall(r"#define (EL_[A-Z0-9_]+)\s+\(?[0-9(]", text)
    constants = [c for c in constants if c not in ("EL_API",)]
    enums = re.findall(r"\b(EL_[A-Z0-9_]+)\s*=\s*\d+", text)
    return structs, constants + enums


def source(header, structs, constants):
    out = ["#include <stddef.h>", "#include <stdio.h>", f'#include "{header}"', "int main(void) {",
           '  printf("{\\"structs\\": {");']
    for i, (name, fields) in enumerate(structs.items()):
        out.append(f'  printf("%s\\"{name}\\": {{\\"size\\": %zu, \\"fields\\": {{", "{"," if i else ""}", sizeof({name}));')
        for j, f in enumerate(fields):
            out.append(f'  printf("%s\\"{f}\\": %zu", "{"," if j else ""}", offsetof({name}, {f}));')
        out.append('  printf("}}");')
    out.append('  printf("}, \\"constants\\": {");')
    for i, c in enumerate(constants):
        out.append(f'  printf("%s\\"{c}\\": %llu", "{"," if i else ""}", (unsigned long long)({c}));')
    out += ['  printf("}}\\n");', "  return 0;", "}"]
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    header, target = sys.argv[1], sys.argv[2]
    structs, constants = parse(header)
    with open(target, "w", encoding="utf-8") as f:
        f.write(source(header, structs, constants))
