package io.concord.bench.jmh;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * One message's way down one agent's stack and up another's, with no sockets: encode, sequence,
 * stamp, CRC-32C and encrypt (AES-GCM, pair key) on the way down, each frame sent as often as the
 * profile says (2 copies on UDP); on the way up, the copy filtered, the other authenticated and
 * decrypted, checked and decoded. A 500-byte content, as in the dissertation's chain test.
 */
@State(Scope.Thread)
public class StackBenchmark {
    private static final Address A_AT = new Address("127.0.0.1", 7001);
    private static final Address B_AT = new Address("127.0.0.1", 7002);

    @Param({"CLASS_7", "CLOSED"})
    public String profile;

    private LayerHarness a;
    private LayerHarness b;
    private AID aAid;
    private AID bAid;
    private String content;

    @Setup(Level.Trial)
    public void setUp() {
        PlatformKey key = PlatformKey.ofHex("000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f");
        SafetyStack.Builder builder = SafetyStack.builder().profile(Profile.valueOf(profile)).platformKey(key)
                .identities(IdentityStore.ephemeral());
        ManualClock clock = new ManualClock();
        a = new LayerHarness("a@bench", clock, builder.build().get().toArray(new io.concord.core.layer.Layer[0]));
        b = new LayerHarness("b@bench", clock, builder.build().get().toArray(new io.concord.core.layer.Layer[0]));
        aAid = new AID("a@bench", A_AT.toUri());
        bAid = new AID("b@bench", B_AT.toUri());
        // A runtime traces only when given a tracer: leave the harness's test tracer out of the figures.
        a.setTracing(false);
        b.setTracing(false);
        content = "s".repeat(500);
        // The first message runs the handshake (class 7); carry frames until it arrives.
        a.sendDown(Envelope.outgoing(message(), bAid, B_AT));
        for (int i = 0; i < 10 && b.upCount() == 0; i++) {
            carry(a, A_AT, b);
            carry(b, B_AT, a);
        }
        if (b.pollUp() == null) {
            throw new IllegalStateException("the handshake did not complete");
        }
    }

    private AclMessage message() {
        return new AclMessage(Performative.INFORM).setSender(aAid).addReceiver(bAid).setContent(content);
    }

    private static void carry(LayerHarness from, Address fromAt, LayerHarness to) {
        Envelope e;
        while ((e = from.pollDown()) != null) {
            to.receiveUp(Envelope.incoming(fromAt, e.data(), e.offset(), e.length(), 0));
        }
    }

    @Benchmark
    public AclMessage downUp() {
        a.sendDown(Envelope.outgoing(message(), bAid, B_AT));
        carry(a, A_AT, b);
        carry(b, B_AT, a); // acknowledgements, every 32 messages
        return b.pollUp().message();
    }
}
