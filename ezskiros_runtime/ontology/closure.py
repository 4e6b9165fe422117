"""Graph closures over plain strings: subclass and sub-property hierarchies.

Kept free of rdflib so the index can compute (and a cached index can carry) its closures
without the RDF library. Real ontologies contain cycles (owl:equivalentClass is one, and
hand-written files sometimes say A subClassOf B subClassOf A), so the closure goes through
strongly connected components instead of assuming a tree or a DAG.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping


def _strongly_connected_components(
    nodes: Iterable[str], edges: Mapping[str, Iterable[str]]
) -> list[list[str]]:
    """Tarjan's algorithm, iterative (deep hierarchies must not hit the recursion limit).

    Components come out in reverse topological order: every component is listed after
    all components it has edges to, which is the order a closure needs.
    """
    index_of: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    components: list[list[str]] = []
    counter = 0
    for root in nodes:
        if root in index_of:
            continue
        work: list[tuple[str, list[str], int]] = [(root, sorted(edges.get(root, ())), 0)]
        index_of[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, successors, position = work[-1]
            if position < len(successors):
                work[-1] = (node, successors, position + 1)
                nxt = successors[position]
                if nxt not in index_of:
                    index_of[nxt] = low[nxt] = counter
                    counter += 1
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, sorted(edges.get(nxt, ())), 0))
                elif nxt in on_stack:
                    low[node] = min(low[node], index_of[nxt])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index_of[node]:
                component: list[str] = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                components.append(component)
    return components


def reflexive_transitive_closure(
    nodes: Iterable[str], edges: Mapping[str, Iterable[str]]
) -> dict[str, frozenset[str]]:
    """For every node (given or reachable): itself and everything reachable from it."""
    all_nodes = set(nodes) | set(edges)
    for targets in edges.values():
        all_nodes.update(targets)
    ordered = sorted(all_nodes)
    closure: dict[str, frozenset[str]] = {}
    for component in _strongly_connected_components(ordered, edges):
        members = set(component)
        reach: set[str] = set(members)
        for node in component:
            for target in edges.get(node, ()):
                if target not in members:
                    reach |= closure[target]
        frozen = frozenset(reach)
        for node in component:
            closure[node] = frozen
    return closure
