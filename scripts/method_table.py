"""method_table.py - the methods of ggxcl's one table (GGX_METHOD_LIST in
kernels/ggx_contract.h) for the project's Python tools: each method's name
and whether it has a dielectric sampler, in id order.

    sys.path.insert(0, "<repository>/scripts"); import method_table
    method_table.names()  # ['ndf', 'heitz', ...]
"""
import os
import re

CONTRACT = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "kernels", "ggx_contract.h")


def methods():
    """(name, has a dielectric sampler) of each entry of GGX_METHOD_LIST, in id order."""
    with open(CONTRACT) as contract:
        text = contract.read()
    entries = re.findall(r'X\((\w+), \w+, "([^"]+)",.*?(?:TANGENT|WORLD),\s*(?:ANISOTROPIC|ISOTROPIC),\s*'
                         r'(?:VNDF|NDF|OWN),\s*(YES|NO),', text, re.DOTALL)
    if not entries:
        raise RuntimeError(f"no GGX_METHOD_LIST entries found in {CONTRACT}")
    return [(name, dielectric == "YES") for _, name, dielectric in entries]


def names():
    return [name for name, _ in methods()]
