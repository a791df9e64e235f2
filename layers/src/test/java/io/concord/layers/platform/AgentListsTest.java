package io.concord.layers.platform;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * Routes followed change by change are the routes a whole rebuild gives, after any sequence of
 * additions, moves and removals in either list (a name in both lists goes to its LAL entry), and a
 * route that went is kept for its grace either way.
 */
class AgentListsTest {

    @Test
    void routesUpdatedByNameEqualRoutesRebuiltWhole() {
        for (long seed = 1; seed <= 200; seed++) {
            SplittableRandom r = new SplittableRandom(seed);
            AgentLists stepwise = new AgentLists();
            AgentLists whole = new AgentLists();
            long now = 0;
            for (int step = 0; step < 50; step++) {
                now += 1_000_000_000L;
                List<String> names = new ArrayList<>();
                for (int k = 1 + r.nextInt(4); k > 0; k--) {
                    String name = "a" + r.nextInt(20) + "@p";
                    names.add(name);
                    boolean local = r.nextBoolean();
                    int what = r.nextInt(3);
                    for (AgentLists l : List.of(stepwise, whole)) {
                        java.util.TreeMap<String, AgentEntry> list = local ? l.lal : l.gal;
                        if (what == 0) {
                            list.remove(name);
                        } else {
                            list.put(name, new AgentEntry(name, "udp://10.200.0." + (1 + what) + ":"
                                    + (7000 + name.length() + what), 1, List.of()));
                        }
                    }
                }
                stepwise.updateRoutes(names, now);
                whole.rebuildRoutes(now);
                for (int i = 0; i < 20; i++) {
                    String n = "a" + i + "@p";
                    for (long later : new long[]{now, now + AgentLists.ROUTE_GRACE_NS - 1}) {
                        assertEquals(whole.route(n, later), stepwise.route(n, later), "seed " + seed + " step " + step + " " + n);
                    }
                }
            }
        }
    }
}
