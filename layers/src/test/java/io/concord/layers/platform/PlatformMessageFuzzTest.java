package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.Envelope;
import io.concord.layers.frame.Frames;
import io.concord.layers.platform.PlatformMessage.Alive;
import io.concord.layers.platform.PlatformMessage.ContainerIs;
import io.concord.layers.platform.PlatformMessage.Join;
import io.concord.layers.platform.PlatformMessage.Joined;
import io.concord.layers.platform.PlatformMessage.LalPage;
import io.concord.layers.platform.PlatformMessage.Leave;
import io.concord.layers.platform.PlatformMessage.Page;
import io.concord.layers.platform.PlatformMessage.Seeking;
import io.concord.layers.platform.PlatformMessage.WhoIsContainer;
import org.junit.jupiter.api.Test;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Platform messages from a member that is not the container, mutated at random from valid ones:
 * whatever arrives, no exception escapes the container layer, nothing reaches the agent above it,
 * each input costs a bounded number of messages sent, and the lists stay bounded. The number of
 * inputs is {@code -Dconcord.fuzz} (100,000 by default, as in CI).
 */
class PlatformMessageFuzzTest {
    private static final int INPUTS = Integer.getInteger("concord.fuzz", 100_000);
    private static final String[] WORDS = {"who-is-container", "container", "seeking", "join", "joined", "lal", "held",
            "alive", "agent-info", "leave", "lal-request", "lal-copy", "gal", "relay-out", "relay-in", "announce",
            "who-is-facilitator", "is-facilitator", "is-not-facilitator", "gal-update", "gal-held", "unknown-secret",
            "contact-me", "term", "seq", "page", "pages", "period", "timeout", "container", "secret", "host"};
    private static final String[] PIECES = {" ", "\n", "=", ",", ";", "%", "%2", "%zz", "-1", "0", "9223372036854775807",
            "99999999999999999999", "udp://127.0.0.1:7002", "udp://[::1]:1", "c@p", "me@p", "y@p", "\u00e9", "\u0000",
            "term=", "page=0", "pages=1000000", "seq=-5", "x".repeat(300)};
    private static final String[] PROTOCOLS = {Protocol.P_DISCOVERY, Protocol.P_LAL, Protocol.P_MAINTENANCE,
            Protocol.P_SERVICES, "concord-network", "concord-relay", "other"};

    @Test
    void noInputEscapesDeliversOrGrowsWithoutBound() {
        assertTimeoutPreemptively(Duration.ofMinutes(5), this::run, "an input hung the container layer");
    }

    private void run() {
        SplittableRandom r = new SplittableRandom(20261123);
        AgentEntry c = OneAgent.other("c", 7002, 1_000);
        AgentEntry y = OneAgent.other("y", 7003, 10);
        List<String> seeds = seeds(c, y);
        OneAgent a = null;
        long maxSent = 0;
        long relayed = 0;
        for (int i = 0; i < INPUTS; i++) {
            if (i % 2_000 == 0) {
                a = fresh(i / 2_000 % 3, c, y);
            }
            String content = mutate(seeds.get(r.nextInt(seeds.size())), r);
            AclMessage m = new AclMessage(Performative.values()[r.nextInt(Performative.values().length)]);
            m.setSender(y.aid());
            m.addReceiver(a.self.aid());
            m.setOntology(Protocol.ONTOLOGY);
            m.setLanguage(Protocol.LANGUAGE);
            m.setProtocol(PROTOCOLS[r.nextInt(PROTOCOLS.length)]);
            m.setContent(content);
            Envelope env = Envelope.outgoing(m, a.self.aid(), null);
            if (r.nextInt(4) == 0) {
                env.putHeader(Frames.ENVELOPE_ANY, Boolean.TRUE);
            }
            a.h.receiveUp(env);
            if (r.nextInt(50) == 0) {
                a.advance(1 + r.nextInt(300));
            }
            Envelope up = a.h.pollUp();
            if (up != null) {
                // Only a relay by this agent's own container reaches the agent (y may have become
                // that container by its own claim: the election trusts members).
                final OneAgent fa = a;
                assertTrue("y@p".equals(a.layer.containerName()) && content.startsWith("relay-in"),
                        () -> "delivered to the agent (role " + fa.role() + ", container " + fa.layer.containerName() + "): "
                                + up.message() + " from: " + content);
                relayed++;
            }
            int sent = 0;
            while (a.h.pollDown() != null) {
                sent++;
            }
            maxSent = Math.max(maxSent, sent);
            assertTrue(sent <= 64, "one input made the agent send " + sent + " messages: " + content);
            assertTrue(a.layer.agents().size() <= 1_000 && a.layer.globalAgents().size() <= 1_000,
                    "the lists grew to " + a.layer.agents().size() + "/" + a.layer.globalAgents().size());
        }
        System.out.println("fuzzed " + INPUTS + " platform messages; at most " + maxSent + " sent for one; "
                + relayed + " relays of the agent's container delivered");
    }

    /** A member (0), a container (1) or a seeker (2), with y listed. */
    private static OneAgent fresh(int kind, AgentEntry c, AgentEntry y) {
        if (kind == 1) {
            OneAgent me = new OneAgent("me", 7001, PlatformConfig.defaults(), NetworkConfig.defaults(), null);
            me.from(y, Performative.INFORM_REF, Protocol.P_LAL, new Join(1, y));
            me.advance(10);
            me.sent();
            return me;
        }
        OneAgent a = new OneAgent("me", 7001, PlatformConfig.defaults(), NetworkConfig.defaults(), null, 7002, 7003);
        if (kind == 0) {
            a.from(c, Performative.INFORM, Protocol.P_DISCOVERY, new ContainerIs(1, c, null));
            a.from(c, Performative.CONFIRM, Protocol.P_LAL, new Joined(1, 40, 250, c));
            a.from(c, Performative.INFORM_REF, Protocol.P_LAL, new LalPage(1, 2, 40, 250,
                    Page.of(0, 1, String.join("\n", AgentLists.pages(List.of(c, y, a.self), 100_000)))));
        }
        a.sent();
        return a;
    }

    private static List<String> seeds(AgentEntry c, AgentEntry y) {
        List<String> s = new ArrayList<>();
        s.add(new WhoIsContainer(1, y).encode());
        s.add(new ContainerIs(7, c, y).encode());
        s.add(new ContainerIs(7, y, y).encode());
        s.add(new Seeking(2, 3, y).encode());
        s.add(new Join(1, y).encode());
        s.add(new Joined(1, 40, 250, y).encode());
        s.add(new Alive(9, 9, 40, 250, y).encode());
        s.add(new Leave(1).encode());
        s.add(new LalPage(9, 9, 40, 250, Page.of(0, 2, String.join("\n", AgentLists.pages(List.of(c, y), 100_000)))).encode());
        s.add("relay-in receiver=me@p\n(inform :sender (agent-identifier :name j@jade) :content \"x\")");
        s.add("relay-out receiver=j@jade addresses=http://127.0.0.1:1/acc\n(inform :sender (agent-identifier :name y@p))");
        s.add("gal-update secret=abc term=1 seq=2 page=0 pages=1\n" + String.join("\n", AgentLists.pages(List.of(y), 100_000)));
        s.add("announce term=1 host=h seq=1\n" + String.join("\n", AgentLists.pages(List.of(y, c), 100_000)));
        return s;
    }

    private static String mutate(String seed, SplittableRandom r) {
        StringBuilder b = new StringBuilder(seed);
        int edits = 1 + r.nextInt(4);
        for (int e = 0; e < edits; e++) {
            int at = b.length() == 0 ? 0 : r.nextInt(b.length() + 1);
            switch (r.nextInt(6)) {
                case 0 -> b.insert(at, PIECES[r.nextInt(PIECES.length)]);
                case 1 -> b.insert(at, WORDS[r.nextInt(WORDS.length)]);
                case 2 -> {
                    int end = Math.min(b.length(), at + r.nextInt(20));
                    b.delete(at, end);
                }
                case 3 -> {
                    if (at < b.length()) {
                        b.setCharAt(at, (char) r.nextInt(0x80));
                    }
                }
                case 4 -> {
                    int end = Math.min(b.length(), at + r.nextInt(40));
                    b.insert(at, b.substring(at, end));
                }
                default -> b.setLength(Math.min(b.length(), at));
            }
        }
        return b.toString();
    }
}
