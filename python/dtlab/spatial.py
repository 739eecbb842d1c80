"""scipy.spatial's Delaunay, ConvexHull and Voronoi in 3D, built on dtlab's exact
Delaunay tetrahedralization:

    from dtlab.spatial import Delaunay, ConvexHull, Voronoi   # instead of scipy.spatial

The attributes, shapes and conventions are scipy's (python/README.md lists them and
where they differ). Every structural decision is an exact sign (adaptive predicates
with symbolic perturbation), so degenerate input (integer lattices, cospherical points,
duplicates) gives the Delaunay tetrahedralization where Qhull raises or returns flat
or overlapping simplices. `check()` proves a result with the exact checker.
"""
from __future__ import annotations

import time
from typing import Any, Callable

import numpy as np

from . import _core
from ._progress import Progress
from ._results import CheckReport, Tetrahedralization

__all__ = ["Delaunay", "ConvexHull", "Voronoi"]

# Facet f of a positively oriented tet (orient3d > 0), counter-clockwise seen from
# outside (oracle/check/facet_table.hpp's facet_vertices).
_OUTWARD_FACETS = np.array([[1, 3, 2], [0, 2, 3], [0, 3, 1], [0, 1, 2]])


def _input_points(points: Any) -> np.ndarray:
    if isinstance(points, np.ma.MaskedArray):
        raise ValueError("Input points cannot be a masked array")
    pts = np.ascontiguousarray(points, dtype=np.float64)
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ValueError(f"dtlab.spatial is 3D: points must be an (n, 3) array, got shape {pts.shape}")
    return pts


def _unsupported(furthest_site: bool, qhull_options: str | None) -> None:
    if furthest_site:
        raise ValueError("furthest_site=True is not supported by dtlab.spatial")
    # qhull_options are accepted and ignored: exact predicates need no joggle or merging.
    del qhull_options


class _Triangulated:
    """The Delaunay tetrahedralization shared by the three classes (scipy's _QhullUser)."""

    def __init__(self, points: Any, incremental: bool, progress: Any) -> None:
        self._incremental = bool(incremental)
        self._progress = progress
        self._build(_input_points(points))

    def _build(self, points: np.ndarray) -> None:
        from . import tetrahedralize  # the package imports this module
        with Progress(self._progress, type(self).__name__, 3) as bar:
            start = time.perf_counter()
            self.points = points
            self.ndim = 3
            self.npoints = len(points)
            self.min_bound = points.min(axis=0) if len(points) else np.zeros(3)
            self.max_bound = points.max(axis=0) if len(points) else np.zeros(3)
            self.tetrahedralization: Tetrahedralization = tetrahedralize(points)
            bar.step("tetrahedralized")
            self._tets = self.tetrahedralization.tets.astype(np.int32)  # orient3d > 0
            self._neighbors = _core.spatial_neighbors(self._tets, len(points))
            bar.step("neighbours")
            self._derive()
            bar.step("attributes")
            self.seconds = time.perf_counter() - start

    def _derive(self) -> None:
        raise NotImplementedError

    def _duplicate_vertices(self) -> tuple[np.ndarray, np.ndarray]:
        """Each duplicate input index and the vertex it repeats (exactly equal coordinates)."""
        dup = self.tetrahedralization.duplicates.astype(np.int64)
        if len(dup) == 0:
            return dup, dup
        at = _core.spatial_locate(self.points, self._tets, self._neighbors, self.points[dup])
        corners = self._tets[at]  # the duplicate is a vertex of the tet that holds it
        same = np.all(self.points[corners] == self.points[dup][:, None, :], axis=2)
        return dup, corners[np.arange(len(dup)), np.argmax(same, axis=1)].astype(np.int64)

    def _hull_triangles(self) -> tuple[np.ndarray, np.ndarray]:
        """The hull facets of the tets, outward and counter-clockwise, and their tets."""
        t, f = np.nonzero(self._neighbors < 0)
        return self._tets[t[:, None], _OUTWARD_FACETS[f]], t

    def add_points(self, points: Any, restart: bool = False) -> None:
        """Adds points (incremental=True only): the tetrahedralization of all points so
        far is rebuilt (it is unique, so `restart` changes nothing)."""
        if not self._incremental:
            raise RuntimeError("incremental mode not enabled or already closed")
        del restart
        self._build(np.concatenate([self.points, _input_points(points)]))

    def close(self) -> None:
        """Ends incremental mode (scipy's close)."""
        self._incremental = False

    def check(self) -> CheckReport:
        """The exact checker's proof (or defects) of the underlying tetrahedralization."""
        from . import check
        return check(self.points, self._tets, "positive", duplicates=self.tetrahedralization.duplicates)

    def _repr_counts(self) -> str:
        raise NotImplementedError

    def __repr__(self) -> str:
        return (f"<dtlab.spatial.{type(self).__name__}: {self.npoints} points, {self._repr_counts()}, "
                f"{len(self.tetrahedralization.duplicates)} duplicates, {self.seconds:.3g} s; exact Delaunay>")

    def _repr_html_(self) -> str:
        return f"<code>{self.__repr__().replace('<', '&lt;').replace('>', '&gt;')}</code>"


def _edges_csr(n: int, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """vertex_neighbor_vertices: (indptr, indices) of the tets' edges, both ways."""
    pairs = tets[:, [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]].reshape(-1, 2).astype(np.int64)
    both = np.concatenate([pairs, pairs[:, ::-1]])
    key = np.unique(both[:, 0] * n + both[:, 1])
    src, dst = key // n, key % n
    indptr = np.searchsorted(src, np.arange(n + 1)).astype(np.int32)
    return indptr, dst.astype(np.int32)


class _Sites(_Triangulated):
    """Delaunay's and Voronoi's constructor: scipy's signature, furthest_site refused."""

    def __init__(self, points: Any, furthest_site: bool = False, incremental: bool = False,
                 qhull_options: str | None = None, *, progress: bool | Callable[..., Any] | None = None) -> None:
        _unsupported(furthest_site, qhull_options)
        self.furthest_site = False
        super().__init__(points, incremental, progress)


class Delaunay(_Sites):
    """scipy.spatial.Delaunay in 3D, from dtlab's exact Delaunay tetrahedralization.

    Attributes as scipy's: points, simplices ((nsimplex, 4) int32, every simplex
    right-handed: det[v1-v0, v2-v0, v3-v0] > 0), neighbors ([i, j] across from vertex
    j, -1 on the hull), equations (lifted hyperplanes, with paraboloid_scale and
    paraboloid_shift), transform (barycentric), vertex_to_simplex, convex_hull,
    coplanar (duplicates: [index, simplex, the vertex it repeats]),
    vertex_neighbor_vertices, nsimplex, npoints, ndim, min_bound, max_bound;
    find_simplex (exact walk: a point on a facet gets one of its tets, -1 only outside
    the hull), plane_distance, lift_points. furthest_site is not supported and
    qhull_options are ignored (no option is needed). Extra: tetrahedralization (the
    dtlab result), check() (the exact proof), seconds.
    """

    def _derive(self) -> None:
        # Swapping the first two vertices makes dtlab's orient3d > 0 right-handed.
        swap = [1, 0, 2, 3]
        self.simplices = np.ascontiguousarray(self._tets[:, swap])
        self.neighbors = np.ascontiguousarray(self._neighbors[:, swap])
        self.nsimplex = len(self.simplices)
        tri, _ = self._hull_triangles()
        self.convex_hull = tri.astype(np.int32)
        self.vertex_to_simplex = np.full(self.npoints, -1, dtype=np.int32)
        self.vertex_to_simplex[self.simplices[::-1].ravel()] = np.repeat(np.arange(self.nsimplex)[::-1], 4)
        dup, orig = self._duplicate_vertices()
        self.vertex_to_simplex[dup] = self.vertex_to_simplex[orig]
        self.coplanar = np.stack([dup, self.vertex_to_simplex[orig], orig], axis=1).astype(np.int32) \
            if len(dup) else np.zeros((0, 3), dtype=np.int32)
        self._lift_scale()
        self._transform: np.ndarray | None = None
        self._equations: np.ndarray | None = None
        self._vnv: tuple[np.ndarray, np.ndarray] | None = None

    def _lift_scale(self) -> None:
        # Qhull's Qbb: the lifted coordinate |x|^2 scaled to [0, largest |coordinate|].
        lift = np.einsum("ij,ij->i", self.points, self.points)
        span = float(lift.max() - lift.min()) if len(lift) else 0.0
        top = float(np.abs(self.points).max()) if len(lift) else 0.0
        self.paraboloid_scale = top / span if span > 0 and top > 0 else 1.0
        self.paraboloid_shift = -float(lift.min()) * self.paraboloid_scale if span > 0 else 0.0

    @property
    def transform(self) -> np.ndarray:
        """(nsimplex, 4, 3): T^-1 in [:, :3] and r = the last vertex in [:, 3], so that
        the barycentric coordinates of x in simplex i are c = T^-1 (x - r), 1 - sum(c).
        As scipy's: NaN for a simplex whose T is too ill-conditioned to invert
        (reciprocal 1-norm condition number below 1000 eps; a valid sliver)."""
        if self._transform is None:
            v = self.points[self.simplices]
            a, b, c = (v[:, k] - v[:, 3] for k in range(3))  # T's columns
            rows = np.stack([np.cross(b, c), np.cross(c, a), np.cross(a, b)], axis=1)
            t = np.stack([a, b, c], axis=2)
            with np.errstate(divide="ignore", invalid="ignore"):
                inv = rows / np.einsum("ij,ij->i", a, rows[:, 0])[:, None, None]  # adj(T) / det(T)
                norm1 = lambda m: np.abs(m).sum(axis=1).max(axis=1)  # noqa: E731 (largest column sum)
                rcond = 1.0 / (norm1(t) * norm1(inv))
            inv[~(rcond >= 1000 * np.finfo(float).eps)] = np.nan
            self._transform = np.concatenate([inv, v[:, 3:4]], axis=1)
        return self._transform

    def lift_points(self, x: Any) -> np.ndarray:
        """Points lifted onto the paraboloid: (..., 4) with the scaled |x|^2 last."""
        x = np.asarray(x, dtype=np.float64)
        z = np.einsum("...i,...i->...", x, x) * self.paraboloid_scale + self.paraboloid_shift
        return np.concatenate([x, z[..., None]], axis=-1)

    @property
    def equations(self) -> np.ndarray:
        """(nsimplex, 5): unit normal and offset of each simplex's lifted hyperplane,
        normal[3] < 0 (the lower hull's outward side)."""
        if self._equations is None:
            z = self.lift_points(self.points)[self.simplices]
            d = z[:, 1:] - z[:, :1]  # (m, 3, 4)
            n = np.stack([(-1) ** c * np.linalg.det(np.delete(d, c, axis=2)) for c in range(4)], axis=1)
            n /= np.linalg.norm(n, axis=1, keepdims=True)
            n *= -np.sign(n[:, 3:4])
            self._equations = np.concatenate([n, -np.einsum("ij,ij->i", n, z[:, 0])[:, None]], axis=1)
        return self._equations

    def plane_distance(self, xi: Any) -> np.ndarray:
        """Distance of lifted xi to every simplex's lifted hyperplane: (..., nsimplex)."""
        z = self.lift_points(xi)
        return z @ self.equations[:, :4].T + self.equations[:, 4]

    @property
    def vertex_neighbor_vertices(self) -> tuple[np.ndarray, np.ndarray]:
        """(indptr, indices): the neighbours of vertex k are indices[indptr[k]:indptr[k+1]]."""
        if self._vnv is None:
            self._vnv = _edges_csr(self.npoints, self.simplices)
        return self._vnv

    def find_simplex(self, xi: Any, bruteforce: bool = False, tol: float | None = None) -> np.ndarray:
        """The simplex holding each point of xi (..., 3), -1 outside the hull. Exact: a
        point on a shared facet, edge or vertex gets one of its simplices, never -1 inside
        the hull (bruteforce and tol are accepted for scipy's signature; no tolerance is
        needed)."""
        del bruteforce, tol
        x = np.asarray(xi, dtype=np.float64)
        if x.shape[-1:] != (3,):
            raise ValueError(f"wrong dimensionality in xi: {x.shape}")
        flat = np.ascontiguousarray(x.reshape(-1, 3))
        return _core.spatial_locate(self.points, self._tets, self._neighbors, flat).reshape(x.shape[:-1])

    def _repr_counts(self) -> str:
        return f"{self.nsimplex} simplices"


class ConvexHull(_Triangulated):
    """scipy.spatial.ConvexHull in 3D: the hull of dtlab's exact Delaunay tetrahedralization.

    simplices ((nfacet, 3) int32, counter-clockwise seen from outside), neighbors ([i, j]
    the facet across the edge opposite vertex j), equations (outward unit normal and
    offset: normal . x + offset <= 0 inside; triangles of one flat face, found by
    exact orientation tests, share one equation), vertices (sorted), volume, area,
    coplanar (duplicates of hull vertices: [index, facet, vertex]), nsimplex, npoints,
    ndim, min_bound, max_bound, good (None). vertices are the hull's corners (points
    on three or more flat faces); points inside a flat face or an edge are not
    corners but are vertices of the triangulation in simplices, where Qhull leaves
    them out. faces: per triangle, its flat face (groups proven coplanar exactly).
    """

    def __init__(self, points: Any, incremental: bool = False, qhull_options: str | None = None, *,
                 progress: bool | Callable[..., Any] | None = None) -> None:
        _unsupported(False, qhull_options)
        self.good = None
        super().__init__(points, incremental, progress)

    def _derive(self) -> None:
        tri, _ = self._hull_triangles()
        self.simplices = tri.astype(np.int32)
        self.nsimplex = len(tri)
        self.neighbors = _triangle_neighbors(tri)
        self.faces = _core.spatial_coplanar_groups(self.points, tri, self.neighbors)
        self.vertices = _extreme_vertices(tri, self.faces)
        self.equations = _face_equations(self.points, tri, self.faces)
        v = self.points[self._tets]
        self.volume = float(np.abs(np.linalg.det(v[:, 1:] - v[:, :1])).sum() / 6.0)
        p = self.points[tri]
        self.area = float(np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum() / 2.0)
        dup, orig = self._duplicate_vertices()
        on_hull = np.isin(orig, self.vertices)
        facet_of = np.full(self.npoints, -1, dtype=np.int64)
        facet_of[tri[::-1].ravel()] = np.repeat(np.arange(len(tri))[::-1], 3)
        self.coplanar = np.stack([dup[on_hull], facet_of[orig[on_hull]], orig[on_hull]], axis=1).astype(np.int32) \
            if on_hull.any() else np.zeros((0, 3), dtype=np.int32)

    def _repr_counts(self) -> str:
        return f"{self.nsimplex} facets in {int(self.faces.max()) + 1 if len(self.faces) else 0} planes"


def _extreme_vertices(tri: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """The hull's corners, sorted: boundary points on three or more flat faces (a point
    inside one face lies on one, inside an edge on two)."""
    pairs = np.unique(np.stack([tri.ravel().astype(np.int64), np.repeat(faces, 3)], axis=1), axis=0)
    v, count = np.unique(pairs[:, 0], return_counts=True)
    return v[count >= 3].astype(np.int32)


def _triangle_neighbors(tri: np.ndarray) -> np.ndarray:
    """[i, j]: the triangle holding the reversed edge opposite corner j (closed surface)."""
    n = int(tri.max()) + 1 if len(tri) else 0
    a = tri[:, [1, 2, 0]].astype(np.int64)
    b = tri[:, [2, 0, 1]].astype(np.int64)
    key = (a * n + b).ravel()
    order = np.argsort(key)
    pos = np.searchsorted(key[order], (b * n + a).ravel())
    return (order[pos] // 3).reshape(-1, 3).astype(np.int32)


def _face_equations(points: np.ndarray, tri: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Outward unit normal and offset per triangle, one equation per flat face (from its
    largest triangle, the best conditioned)."""
    p = points[tri]
    cross = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    size = np.linalg.norm(cross, axis=1)
    best = np.full(int(faces.max()) + 1 if len(faces) else 0, -1, dtype=np.int64)
    order = np.argsort(size)  # ascending: the largest triangle of each face is written last
    best[faces[order]] = order
    normal = cross[best] / size[best][:, None]
    offset = -np.einsum("ij,ij->i", normal, p[best, 0])
    return np.concatenate([normal, offset[:, None]], axis=1)[faces]


def _circumcenters(p: np.ndarray) -> np.ndarray:
    """Circumcentres of (m, 4, 3) tets: solve 2 (v_k - v_0) . c = |v_k|^2 - |v_0|^2."""
    d = p[:, 1:] - p[:, :1]
    rhs = 0.5 * np.einsum("mki,mki->mk", d, d)
    return p[:, 0] + np.linalg.solve(d, rhs[..., None])[..., 0]


class Voronoi(_Sites):
    """scipy.spatial.Voronoi in 3D, the dual of dtlab's exact Delaunay tetrahedralization.

    vertices (one per cell of the Delaunay complex: tets sharing a circumsphere, found
    by exact insphere tests, give one vertex, not several nearby copies), regions (per
    distinct input point the vertex indices of its cell, -1 when it is unbounded),
    point_region (a duplicate gets the region of the point it repeats), ridge_points,
    ridge_vertices (in cyclic order around the ridge, -1 once for an unbounded ridge),
    ridge_dict, npoints, ndim, min_bound, max_bound. Unlike scipy's default (Qz) no
    empty region is added for a point at infinity.
    """

    def _derive(self) -> None:
        group = _core.spatial_cospherical_groups(self.points, self._tets, self._neighbors)
        self._group = group
        count = int(group.max()) + 1 if len(group) else 0
        first = np.full(count, -1, dtype=np.int64)
        first[group[::-1]] = np.arange(len(group))[::-1]
        self.vertices = _circumcenters(self.points[self._tets[first]]) if count else np.zeros((0, 3))
        self._regions()
        r = _core.spatial_voronoi_ridges(self._tets, self.npoints, self._neighbors, group)
        self.ridge_points = r["points"].astype(np.int32)
        off, verts = r["offsets"], r["vertices"]
        self.ridge_vertices = [verts[off[i]:off[i + 1]].tolist() for i in range(len(off) - 1)]

    def _regions(self) -> None:
        pairs = np.unique(np.stack([self._tets.ravel().astype(np.int64), np.repeat(self._group, 4)], axis=1), axis=0)
        hull = np.unique(self._hull_triangles()[0])
        dup, orig = self._duplicate_vertices()
        sites = np.setdiff1d(np.arange(self.npoints), dup)
        region_of = np.full(self.npoints, -1, dtype=np.int64)
        region_of[sites] = np.arange(len(sites))
        region_of[dup] = region_of[orig]
        self.point_region = region_of.astype(np.intp)
        cut = np.searchsorted(pairs[:, 0], sites)
        ends = np.searchsorted(pairs[:, 0], sites, side="right")
        unbounded = np.isin(sites, hull)
        self.regions = [([-1] if u else []) + pairs[a:b, 1].tolist() for a, b, u in zip(cut, ends, unbounded)]

    @property
    def ridge_dict(self) -> dict[tuple[int, int], list[int]]:
        """{(p, q): ridge vertices}, as scipy's."""
        return {(int(p), int(q)): v for (p, q), v in zip(self.ridge_points, self.ridge_vertices)}

    def _repr_counts(self) -> str:
        return f"{len(self.vertices)} vertices, {len(self.ridge_points)} ridges"
