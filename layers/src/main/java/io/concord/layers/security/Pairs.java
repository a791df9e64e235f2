package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The {@link Handshake}'s pairs by peer id, least recently used first. Only this agent's own sends
 * and signed handshakes create one, so strangers cannot push real pairs out; one pushed out by
 * this agent's own traffic to more than {@link #MAX_PAIRS} peers has its waiting messages counted
 * as dropped. Loop thread only.
 */
final class Pairs {
    static final int MAX_PAIRS = 4096;

    private final Map<Long, Pair> pairs = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Pair> eldest) {
            if (size() > MAX_PAIRS) {
                evicted.add(eldest.getValue());
                return true;
            }
            return false;
        }
    };
    private final List<Pair> evicted = new ArrayList<>();

    /** The pair with a peer, or {@code null} (a use: the pair becomes the most recently used). */
    Pair get(long peerId) {
        return pairs.get(peerId);
    }

    /** The pair with a peer, made if there is none; a pair pushed out for it has its messages dropped. */
    Pair getOrAdd(LayerContext ctx, long peerId) {
        Pair p = pairs.computeIfAbsent(peerId, k -> new Pair());
        dropEvicted(ctx);
        return p;
    }

    int size() {
        return pairs.size();
    }

    /** Counts the messages of pairs pushed out of the table: nothing is lost uncounted. */
    private void dropEvicted(LayerContext ctx) {
        for (Pair gone : evicted) {
            if (gone.timer >= 0) {
                ctx.host().cancel(gone.timer);
            }
            for (Envelope e : gone.queue) {
                ctx.drop(e, "pair-evicted", "more than " + MAX_PAIRS + " peers: the least recently used pair was forgotten");
            }
            gone.queue.clear();
        }
        evicted.clear();
    }
}
