"""test_stubs.py - the type stubs (ggxcl/__init__.pyi) against the module:
the same public names, and for every function and method the same
parameters, in order, with the same keyword-only ones and the same
defaults, as the signature pybind11 writes at the top of its docstring;
properties are properties in both.  Run by CTest with test_ggxcl.py.
"""
import ast
import pathlib

import pytest

import ggxcl

STUB = pathlib.Path(ggxcl.__file__).with_name("__init__.pyi")


def split_top_level(text):
    """Splits `text` at commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    parts.append(text[start:].strip())
    return [p for p in parts if p]


def doc_parameters(function):
    """[(name, keyword_only, default text or None)] from pybind11's docstring signature, self left out."""
    line = function.__doc__.splitlines()[0]
    inside = line[line.index("(") + 1:line.rindex(") ->")]
    params, keyword_only = [], False
    for part in split_top_level(inside):
        if part == "*":
            keyword_only = True
            continue
        name = part.split(":")[0].split("=")[0].strip()
        default = part.split("=", 1)[1].strip() if "=" in part else None
        if name != "self":
            params.append((name, keyword_only, default))
    return params


def stub_parameters(node):
    args = node.args
    positional = [a.arg for a in args.posonlyargs + args.args if a.arg != "self"]
    defaults = [None] * (len(positional) - len(args.defaults)) + [ast.unparse(d) for d in args.defaults]
    params = [(n, False, d) for n, d in zip(positional, defaults)]
    params += [(a.arg, True, None if d is None else ast.unparse(d)) for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    return params


def same_default(doc, stub):
    if doc is None or stub is None:
        return doc == stub
    return doc == stub or ast.literal_eval(doc) == ast.literal_eval(stub)


def stub_tree():
    return ast.parse(STUB.read_text())


def stub_functions():
    """(qualified name, the module's object, the stub's FunctionDef) for every def in the stub."""
    found = []
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            found.append((node.name, getattr(ggxcl, node.name), node))
        if isinstance(node, ast.ClassDef):
            for member in node.body:
                if isinstance(member, ast.FunctionDef):
                    found.append((f"{node.name}.{member.name}", getattr(ggxcl, node.name).__dict__.get(member.name),
                                  member))
    return found


def test_the_stub_names_every_public_name_and_no_other():
    names = set()
    for node in stub_tree().body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    public = {n for n in dir(ggxcl) if not n.startswith("_")} | {"__version__"}
    assert names - {"Alpha", "Vector"} == public


@pytest.mark.parametrize("name,actual,node", stub_functions(), ids=lambda v: v if isinstance(v, str) else "")
def test_every_stub_signature_matches_the_module(name, actual, node):
    assert actual is not None, f"{name} is in the stub, not in the module"
    is_property = any(ast.unparse(d) == "property" for d in node.decorator_list)
    assert is_property == isinstance(actual, property), name
    if is_property:
        return
    doc, stub = doc_parameters(actual), stub_parameters(node)
    assert [p[:2] for p in doc] == [p[:2] for p in stub], name
    for (param, _, d), (_, _, s) in zip(doc, stub):
        assert same_default(d, s), f"{name}: {param} defaults to {d} in the module, {s} in the stub"


def test_the_signature_check_sees_a_wrong_stub():
    # Control: a stub with two keyword arguments swapped, or a default changed, does not match.
    node = next(n for q, _, n in stub_functions() if q == "Sampler.sample")
    doc = doc_parameters(ggxcl.Sampler.sample)
    swapped = ast.parse(ast.unparse(node))
    kw = swapped.body[0].args.kwonlyargs
    kw[0], kw[1] = kw[1], kw[0]
    assert [p[:2] for p in stub_parameters(swapped.body[0])] != [p[:2] for p in doc]
    changed = ast.parse(ast.unparse(node)).body[0]
    theta = [a.arg for a in changed.args.kwonlyargs].index("theta")
    changed.args.kw_defaults[theta] = ast.Constant(45.0)
    assert any(not same_default(d, s) for (_, _, d), (_, _, s) in zip(doc, stub_parameters(changed)))


def test_the_stub_names_every_public_member_of_sampler_and_no_other():
    cls = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == "Sampler")
    members = {m.name for m in cls.body if isinstance(m, ast.FunctionDef)}
    members |= {m.target.id for m in cls.body if isinstance(m, ast.AnnAssign)}
    assert members - {"__init__"} == {n for n in dir(ggxcl.Sampler) if not n.startswith("_")}


def documented(tree):
    """(object path, docstring) of every documented class, method and function of the stubs."""
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and ast.get_docstring(node):
            yield (node.name,), ast.get_docstring(node)
        if isinstance(node, ast.ClassDef):
            if ast.get_docstring(node):
                yield (node.name,), ast.get_docstring(node)
            for member in node.body:
                if isinstance(member, ast.FunctionDef) and ast.get_docstring(member):
                    yield (node.name, member.name), ast.get_docstring(member)


def test_help_shows_the_stubs_docstrings():
    """help() explains every argument: each binding carries its stub's docstring (python/pyi_docs.py)."""
    tree = ast.parse(STUB.read_text())
    checked = 0
    for path, doc in documented(tree):
        obj = ggxcl
        for name in path:
            obj = getattr(obj, name)
        assert doc in (obj.__doc__ or ""), f"{'.'.join(path)}: the binding's docstring is not the stub's"
        checked += 1
    assert checked >= 10
