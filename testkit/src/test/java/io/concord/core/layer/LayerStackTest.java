package io.concord.core.layer;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertSame;

class LayerStackTest {

    private static final class Recording extends Layer {
        private final String name;
        private final List<String> log;

        Recording(String name, List<String> log) {
            this.name = name;
            this.log = log;
        }

        @Override
        public String name() {
            return name;
        }

        @Override
        public void init(LayerContext ctx) {
            log.add("init " + name);
        }

        @Override
        public void start(LayerContext ctx) {
            log.add("start " + name);
        }

        @Override
        public void stop(LayerContext ctx) {
            log.add("stop " + name);
        }

        @Override
        public void onDown(LayerContext ctx, Envelope env) {
            log.add("down " + name);
            ctx.passDown(env);
        }

        @Override
        public void onUp(LayerContext ctx, Envelope env) {
            log.add("up " + name);
            ctx.passUp(env);
        }
    }

    private static Envelope outgoing() {
        return Envelope.outgoing(new AclMessage(Performative.INFORM), new AID("b@p"), new Address("h", 1));
    }

    @Test
    void startsBottomUpStopsTopDownAndPassesInLayerOrder() {
        List<String> log = new ArrayList<>();
        LayerHarness h = new LayerHarness(new Recording("top", log), new Recording("bottom", log));
        h.sendDown(outgoing());
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[1], 0, 1, 0));
        h.stop();
        assertEquals(List.of("init bottom", "init top", "start bottom", "start top", "down top", "down bottom",
                "up bottom", "up top", "stop top", "stop bottom"), log);
        assertNotNull(h.pollDown());
        assertNotNull(h.pollUp());
    }

    @Test
    void aLayerFindsAnotherOfItsStackThroughItsContextTopmostFirst() {
        List<String> log = new ArrayList<>();
        Recording upper = new Recording("upper", log);
        Recording lower = new Recording("lower", log);
        Layer[] seen = new Layer[2];
        Layer bottom = new Layer() {
            @Override
            public void start(LayerContext ctx) {
                seen[0] = ctx.find(Recording.class);
                seen[1] = ctx.find(CodecLayer.class);
            }
        };
        new LayerHarness(upper, lower, bottom);
        assertSame(upper, seen[0]);
        assertNull(seen[1]);
    }

    @Test
    void aLayerThatThrowsLosesOnlyThatMessageWhichIsCountedAsALayerError() {
        Layer faulty = new Layer() {
            @Override
            public void onDown(LayerContext ctx, Envelope env) {
                if (env.message().getContent() != null) {
                    throw new IllegalStateException("boom");
                }
                ctx.passDown(env);
            }
        };
        LayerHarness h = new LayerHarness(faulty);
        Envelope bad = outgoing();
        bad.message().setContent("x");
        h.sendDown(bad);
        assertNull(h.pollDown());
        assertEquals(1, h.drops().get("layer-error"));
        Envelope good = outgoing();
        h.sendDown(good);
        assertSame(good, h.pollDown(), "the stack goes on after a failure");
    }

    @Test
    void aLayerThatThrowsOnEveryFrameLogsOneStackTraceNotOneAFrame() {
        Layer faulty = new Layer() {
            @Override
            public void onDown(LayerContext ctx, Envelope env) {
                throw new IllegalStateException("boom");
            }
        };
        LayerHarness h = new LayerHarness(faulty);
        for (int i = 0; i < 1_000; i++) {
            h.sendDown(outgoing());
        }
        assertEquals(1_000, h.drops().get("layer-error"), "every one counted");
        assertEquals(1, h.tracesLogged(), "one stack trace in the log");
    }

    @Test
    void aDropIsCountedUnderItsReasonAndTraced() {
        Layer dropper = new Layer() {
            @Override
            public void onUp(LayerContext ctx, Envelope env) {
                ctx.drop(env, "too-old", "timestamp 5 s in the past");
            }
        };
        LayerHarness h = new LayerHarness(dropper);
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[3], 0, 3, 0));
        assertNull(h.pollUp());
        assertEquals(1, h.drops().get("too-old"));
        assertEquals(1, h.drops().total());
        assertEquals(1, h.trace().count());
        assertTrue(h.trace().lastLines().get(0).contains("timestamp 5 s in the past"), "the trace says why");
        h.setTracing(false);
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[3], 0, 3, 0));
        assertEquals(2, h.drops().get("too-old"), "counted with tracing off too");
        assertEquals(1, h.trace().count(), "not traced with tracing off");
    }

    @Test
    void theCodecLayerDropsWhatDoesNotDecodeAndPassesWhatDoes() {
        LayerHarness h = new LayerHarness(new CodecLayer());
        Envelope out = outgoing();
        out.message().setContent("hello");
        h.sendDown(out);
        Envelope wire = h.pollDown();
        h.receiveUp(Envelope.incoming(new Address("h", 2), wire.data(), wire.offset(), wire.length(), 0));
        assertEquals("hello", h.pollUp().message().getContent());
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[]{1, 2, 3}, 0, 3, 0));
        assertNull(h.pollUp());
        assertEquals(1, h.drops().get("malformed"));
    }

    @Test
    void eventsTravelOnTheirOwnPath() {
        List<String> seen = new ArrayList<>();
        Layer watcher = new Layer() {
            @Override
            public void onEvent(LayerContext ctx, StackEvent event) {
                seen.add(event.type());
                ctx.fireEvent(event);
            }
        };
        LayerHarness h = new LayerHarness(watcher);
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[1], 0, 1, 0));
        assertEquals(List.of(), seen, "data is not an event");
        new io.concord.core.layer.LayerStack(List.of(watcher), h, e -> { }, e -> { }, e -> seen.add("out:" + e.type()))
                .fireEvent(new StackEvent("suspect", null, true));
        assertEquals(List.of("suspect", "out:suspect"), seen);
    }

    @Test
    void aLayerTimerFiresWhenTheHarnessAdvancesTime() {
        List<Long> firedAt = new ArrayList<>();
        Layer timed = new Layer() {
            @Override
            public void start(LayerContext ctx) {
                ctx.host().schedule(ctx.nowNs() + 10_000_000L, () -> firedAt.add(ctx.nowNs()));
            }
        };
        LayerHarness h = new LayerHarness(timed);
        h.advanceMs(9);
        assertEquals(List.of(), firedAt);
        h.advanceMs(1);
        assertEquals(List.of(10_000_000L), firedAt);
    }
}
