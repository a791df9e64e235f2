package io.concord.agents.plan;

import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * The route graph in arrays, for A*: nodes by index with their positions, edges in compressed
 * adjacency lists with their lengths and doors. Built once from a map (or any graph), immutable.
 */
public final class RouteGraph {
    final int[] ids;
    final double[] xs;
    final double[] ys;
    final int[] firstEdge;
    final int[] edgeTo;
    final double[] edgeLength;
    final String[] edgeDoor;
    private final Map<Integer, Integer> index = new HashMap<>();

    private RouteGraph(int[] ids, double[] xs, double[] ys, int[][] edges, double[] lengths, String[] doors) {
        this.ids = ids;
        this.xs = xs;
        this.ys = ys;
        for (int i = 0; i < ids.length; i++) {
            if (index.put(ids[i], i) != null) {
                throw new IllegalArgumentException("node " + ids[i] + " is given twice");
            }
        }
        int n = ids.length;
        int[] degree = new int[n + 1];
        for (int[] e : edges) {
            degree[idx(e[0])]++;
            degree[idx(e[1])]++;
        }
        firstEdge = new int[n + 1];
        for (int i = 0; i < n; i++) {
            firstEdge[i + 1] = firstEdge[i] + degree[i];
        }
        int[] fill = Arrays.copyOf(firstEdge, n);
        edgeTo = new int[2 * edges.length];
        edgeLength = new double[2 * edges.length];
        edgeDoor = new String[2 * edges.length];
        for (int k = 0; k < edges.length; k++) {
            int a = idx(edges[k][0]);
            int b = idx(edges[k][1]);
            int ea = fill[a]++;
            int eb = fill[b]++;
            edgeTo[ea] = b;
            edgeTo[eb] = a;
            edgeLength[ea] = edgeLength[eb] = lengths[k];
            edgeDoor[ea] = edgeDoor[eb] = doors[k];
        }
    }

    private int idx(int id) {
        Integer i = index.get(id);
        if (i == null) {
            throw new IllegalArgumentException("no node " + id);
        }
        return i;
    }

    /** The graph of a map: its nodes, and its edges with their lengths and doors. */
    public static RouteGraph of(HospitalMap map) {
        var nodes = map.nodes();
        int[] ids = new int[nodes.size()];
        double[] xs = new double[ids.length];
        double[] ys = new double[ids.length];
        for (int i = 0; i < ids.length; i++) {
            Node n = nodes.get(i);
            ids[i] = n.id();
            xs[i] = n.at().x();
            ys[i] = n.at().y();
        }
        var edges = map.edges();
        int[][] es = new int[edges.size()][];
        double[] ls = new double[es.length];
        String[] ds = new String[es.length];
        for (int k = 0; k < es.length; k++) {
            Edge e = edges.get(k);
            es[k] = new int[] {e.a(), e.b()};
            ls[k] = e.length(map);
            ds[k] = e.door();
        }
        return new RouteGraph(ids, xs, ys, es, ls, ds);
    }

    /**
     * Any graph: node ids with positions, and edges as id pairs (lengths are the straight
     * distances); for tests and benchmarks.
     */
    public static RouteGraph of(int[] ids, double[] xs, double[] ys, int[][] edges) {
        double[] ls = new double[edges.length];
        RouteGraph probe = new RouteGraph(ids, xs, ys, new int[0][], new double[0], new String[0]);
        for (int k = 0; k < edges.length; k++) {
            int a = probe.idx(edges[k][0]);
            int b = probe.idx(edges[k][1]);
            ls[k] = Math.hypot(xs[a] - xs[b], ys[a] - ys[b]);
        }
        return new RouteGraph(ids, xs, ys, edges, ls, new String[edges.length]);
    }

    /**
     * A generated graph for tests and benchmarks: a {@code w} x {@code h} grid with 1 m spacing,
     * each node jittered by up to 0.3 m, each edge removed with probability {@code removed}.
     */
    public static RouteGraph grid(int w, int h, double removed, long seed) {
        java.util.SplittableRandom r = new java.util.SplittableRandom(seed);
        int n = w * h;
        int[] ids = new int[n];
        double[] xs = new double[n];
        double[] ys = new double[n];
        for (int i = 0; i < n; i++) {
            ids[i] = i;
            xs[i] = i % w + 0.3 * r.nextDouble();
            ys[i] = i / w + 0.3 * r.nextDouble();
        }
        java.util.List<int[]> edges = new java.util.ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (i % w < w - 1 && r.nextDouble() >= removed) {
                edges.add(new int[] {i, i + 1});
            }
            if (i / w < h - 1 && r.nextDouble() >= removed) {
                edges.add(new int[] {i, i + w});
            }
        }
        return of(ids, xs, ys, edges.toArray(new int[0][]));
    }

    /** Nodes in the graph. */
    public int size() {
        return ids.length;
    }

    /** True if the graph has this node. */
    public boolean has(int id) {
        return index.containsKey(id);
    }

    int indexOf(int id) {
        return idx(id);
    }
}
