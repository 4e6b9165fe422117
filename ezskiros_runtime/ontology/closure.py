"""Hierarchies over plain strings (subclasses, sub-properties), answered on demand.

Kept free of rdflib so the index can answer from its direct edges, cached or built. The
closure is never materialised: a chain of 10,000 ``rdfs:subClassOf`` has 50 million
(class, ancestor) pairs, which took 3 GB in memory and 251 MB in the cache when every
class kept its frozenset of ancestors. A `Hierarchy` keeps the direct edges (linear in the
triples) and walks them when asked, keeping recent answers within ``MEMO_BUDGET`` members.

Real ontologies contain cycles (owl:equivalentClass is one, and hand-written files
sometimes say A subClassOf B subClassOf A); a walk with a visited set handles them, and the
one computation that needs a DAG (``ancestor_count``) goes through strongly connected
components. Every walk is iterative: deep hierarchies must not hit the recursion limit.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

MEMO_BUDGET = 200_000
"""Members of remembered answers kept at most (all sets together): bounded memory, and a
repeated question (the checks ask the same few classes again and again) costs a lookup."""


class Hierarchy:
    """Direct edges ``node -> parents`` and the reflexive, transitive questions on them."""

    __slots__ = ("_counts", "_down", "_memo", "_memo_size", "_up")

    def __init__(self, nodes: Iterable[str], edges: Mapping[str, Iterable[str]]) -> None:
        up: dict[str, tuple[str, ...]] = {node: () for node in nodes}
        for node, targets in edges.items():
            up[node] = tuple(sorted(set(targets) - {node}))
            for target in up[node]:
                up.setdefault(target, ())
        self._up = up
        self._down: dict[str, tuple[str, ...]] | None = None
        self._memo: dict[tuple[bool, str], frozenset[str]] = {}
        self._memo_size = 0
        self._counts: dict[str, int] | None = None

    def __contains__(self, node: object) -> bool:
        return node in self._up

    def parents(self, node: str) -> tuple[str, ...]:
        """The direct edges of ``node`` (itself excluded), sorted."""
        return self._up.get(node, ())

    def ancestors(self, node: str) -> frozenset[str]:
        """``node`` and everything reachable from it upwards (``{node}`` if unknown)."""
        return self._reach(node, upwards=True)

    def descendants(self, node: str) -> frozenset[str]:
        """``node`` and everything that reaches it (``{node}`` if unknown)."""
        return self._reach(node, upwards=False)

    def reaches(self, low: str, high: str) -> bool:
        """Whether ``high`` is among the ancestors of ``low`` (reflexive)."""
        if low == high:
            return True
        if (True, low) in self._memo:
            return high in self._memo[(True, low)]
        return low in self._reach(high, upwards=False)

    def _reach(self, node: str, upwards: bool) -> frozenset[str]:
        key = (upwards, node)
        found = self._memo.get(key)
        if found is not None:
            return found
        if node not in self._up:
            return frozenset((node,))
        edges = self._up if upwards else self._reverse()
        seen = {node}
        stack = [node]
        while stack:
            for nxt in edges.get(stack.pop(), ()):
                if nxt not in seen:
                    seen.add(nxt)
                    stack.append(nxt)
        result = frozenset(seen)
        if self._memo_size + len(result) > MEMO_BUDGET:
            self._memo.clear()
            self._memo_size = 0
        if len(result) <= MEMO_BUDGET:
            self._memo[key] = result
            self._memo_size += len(result)
        return result

    def _reverse(self) -> dict[str, tuple[str, ...]]:
        if self._down is None:
            down: dict[str, list[str]] = {}
            for node, targets in self._up.items():
                for target in targets:
                    down.setdefault(target, []).append(node)
            self._down = {node: tuple(sorted(found)) for node, found in down.items()}
        return self._down

    def ancestor_count(self, node: str) -> int:
        """``len(ancestors(node))``, for every node in linear time along chains and trees.

        A strongly connected component with one parent component has that parent's count
        plus its own size (no ancestor is counted twice); only a node with several parent
        components is walked. Computed for all nodes at the first call."""
        if self._counts is None:
            self._counts = self._all_counts()
        return self._counts.get(node, 1)

    def _all_counts(self) -> dict[str, int]:
        counts: dict[str, int] = {}
        for component in strongly_connected_components(sorted(self._up), self._up):
            members = set(component)
            outside = {t for node in component for t in self._up[node] if t not in members}
            if not outside:
                count = len(members)
            elif len(outside) == 1:
                count = len(members) + counts[next(iter(outside))]
            else:
                count = len(self._reach(component[0], upwards=True))
            for node in component:
                counts[node] = count
        return counts

    def edges(self) -> dict[str, tuple[str, ...]]:
        """The direct edges of the nodes that have any (for the cache)."""
        return {node: targets for node, targets in self._up.items() if targets}


def strongly_connected_components(
    nodes: Iterable[str], edges: Mapping[str, Iterable[str]]
) -> list[list[str]]:
    """Tarjan's algorithm, iterative (deep hierarchies must not hit the recursion limit).

    Components come out in reverse topological order: every component is listed after
    all components it has edges to, which is the order a bottom-up computation needs.
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
