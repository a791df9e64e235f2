package io.concord.agents.plan;

import io.concord.agents.map.HospitalMap;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A* on the route graph, and the agents' content format. */
class PlanTest {
    private final HospitalMap map = HospitalMap.defaultHospital();
    private final AStar astar = new AStar(RouteGraph.of(map), 0);

    @Test
    void theScenarioRoutesPassTheirDoors() {
        Route r = astar.find(19, 3);
        assertEquals(List.of(19, 22, 7, 6, 5, 4, 2, 3), r.nodes());
        assertEquals(List.of("WA", "A2"), r.doors());
        Route r2 = astar.find(3, 9);
        assertEquals(List.of("A2", "WA", "WB", "B7"), r2.doors());
        assertEquals(r2.lengthM(), sum(r2), 1e-9);
    }

    private double sum(Route r) {
        double s = 0;
        for (int i = 1; i < r.nodes().size(); i++) {
            s += map.node(r.nodes().get(i - 1)).at().distanceTo(map.node(r.nodes().get(i)).at());
        }
        return s;
    }

    @Test
    void aBlockedEdgeOrARefusingDoorIsAvoidedOrThereIsNoRoute() {
        // The lobby has a triangle: block 22-19 and the route goes round by 23.
        Route r = astar.find(22, 19, Set.of(AStar.edgeKey(19, 22)), d -> true);
        assertEquals(List.of(22, 23, 19), r.nodes());
        // Ward B is reached only through WB.
        assertNull(astar.find(19, 9, Set.of(), d -> !d.equals("WB")));
        assertThrows(IllegalArgumentException.class, () -> astar.find(19, 99));
    }

    @Test
    void aStarFindsTheShortestRouteOnAGeneratedGraph() {
        RouteGraph g = RouteGraph.grid(32, 32, 0.2, 5);
        AStar a = new AStar(g, 0);
        // Against Dijkstra by brute force (A* with a zero heuristic is Dijkstra: compare lengths).
        SplittableRandom r = new SplittableRandom(1);
        for (int k = 0; k < 50; k++) {
            int s = r.nextInt(1024);
            int t = r.nextInt(1024);
            Route route = a.find(s, t);
            double d = dijkstra(g, s, t);
            if (route == null) {
                assertEquals(Double.MAX_VALUE, d);
            } else {
                assertEquals(d, route.lengthM(), 1e-9);
            }
        }
    }

    /** Plain Dijkstra in O(n²) over the graph's arrays, as the reference. */
    private static double dijkstra(RouteGraph g, int s, int t) {
        int n = g.size();
        double[] d = new double[n];
        boolean[] done = new boolean[n];
        java.util.Arrays.fill(d, Double.MAX_VALUE);
        d[g.indexOf(s)] = 0;
        for (int k = 0; k < n; k++) {
            int u = -1;
            for (int i = 0; i < n; i++) {
                if (!done[i] && d[i] != Double.MAX_VALUE && (u < 0 || d[i] < d[u])) {
                    u = i;
                }
            }
            if (u < 0) {
                break;
            }
            done[u] = true;
            for (int e = g.firstEdge[u]; e < g.firstEdge[u + 1]; e++) {
                int v = g.edgeTo[e];
                d[v] = Math.min(d[v], d[u] + g.edgeLength[e]);
            }
        }
        return d[g.indexOf(t)];
    }
}
