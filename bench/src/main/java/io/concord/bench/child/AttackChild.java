package io.concord.bench.child;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.net.SocketNetwork;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The attacker of {@code bench/run attack}, in a JVM of its own: floods a running platform's agents
 * until its standard input closes, then prints {@code SENT <count>}.
 * <ul>
 *   <li>{@code forged}: an outsider's frames (no key): a third random bytes, a third Concord
 *       headers for the agent with random source ids and a random sealed body, a third "for any
 *       agent" frames with a random body.</li>
 *   <li>{@code handshake}: a key holder's new identities: each a new agent name (a fresh Ed25519
 *       identity) that sends one message to an agent of the platform, so a signed handshake each.</li>
 *   <li>{@code tcp}: TCP streams that announce 1 MiB frames and send a few bytes of them, opened
 *       again as the agents close them.</li>
 *   <li>{@code cpu}: the control: no attack, one core kept busy, as an attacker on this machine keeps one.</li>
 * </ul>
 * Arguments: kind, platform name, platform key (hex), then the agents as {@code name@platform=host:port}.
 */
public final class AttackChild {
    private AttackChild() {
    }

    public static void main(String[] args) throws Exception {
        String kind = args[0];
        String platform = args[1];
        PlatformKey key = PlatformKey.ofHex(args[2]);
        List<AID> targets = new ArrayList<>();
        List<InetSocketAddress> at = new ArrayList<>();
        for (int i = 3; i < args.length; i++) {
            String[] nv = args[i].split("=");
            String[] hp = nv[1].split(":");
            at.add(new InetSocketAddress(hp[0], Integer.parseInt(hp[1])));
            targets.add(new AID(nv[0], (kind.equals("tcp") ? "tcp://" : "udp://") + nv[1]));
        }
        AtomicBoolean running = new AtomicBoolean(true);
        AtomicLong sent = new AtomicLong();
        Thread flood = new Thread(() -> {
            try {
                switch (kind) {
                    case "forged" -> forged(targets, at, key.frameKeyBits(), running, sent);
                    case "handshake" -> handshakes(platform, key, targets, running, sent);
                    case "tcp" -> tcp(at, running, sent);
                    case "cpu" -> {
                        // The control: no attack, only a core kept busy, as each attacker keeps one.
                        long x = 0;
                        while (running.get()) {
                            x += System.nanoTime() & 1;
                        }
                        sent.set(x == -1 ? 1 : 0);
                    }
                    default -> throw new IllegalArgumentException("unknown attack " + kind);
                }
            } catch (Exception | Error e) {
                System.out.println("FAILED " + e);
                System.out.flush();
            }
        }, "attack");
        flood.setDaemon(true);
        flood.start();
        System.out.println("READY");
        System.out.flush();
        while (System.in.read() >= 0) {
            // until the harness closes our input
        }
        running.set(false);
        flood.join(5_000);
        System.out.println("SENT " + sent.get());
        System.out.flush();
    }

    private static void forged(List<AID> targets, List<InetSocketAddress> at, int keyBits, AtomicBoolean running, AtomicLong sent)
            throws IOException {
        SplittableRandom r = new SplittableRandom(17);
        long[] ids = new long[targets.size()];
        for (int i = 0; i < ids.length; i++) {
            ids[i] = Frames.id(targets.get(i).name());
        }
        byte[] b = new byte[1_200];
        try (DatagramChannel ch = DatagramChannel.open()) {
            while (running.get()) {
                int t = r.nextInt(targets.size());
                int len = 48 + r.nextInt(600);
                for (int i = 0; i < len; i++) {
                    b[i] = (byte) r.nextInt();
                }
                int shape = (int) (sent.get() % 3);
                if (shape > 0) {
                    ByteBuffer h = ByteBuffer.wrap(b);
                    h.putShort((short) Frames.MAGIC).put((byte) Frames.VERSION)
                            // The key's id is on every frame of the platform: an outsider copies it.
                            .put((byte) ((shape == 1 ? Frames.PROTECTION_GCM_PAIR : Frames.PROTECTION_GCM_PLATFORM) | keyBits))
                            .putLong(r.nextLong()).putLong(shape == 1 ? ids[t] : Frames.ANY).putLong(r.nextLong());
                }
                ch.send(ByteBuffer.wrap(b, 0, len), at.get(t));
                sent.incrementAndGet();
            }
        }
    }

    /** A new agent per handshake, in a runtime of the attacker's own with the platform's key. */
    private static void handshakes(String platform, PlatformKey key, List<AID> targets, AtomicBoolean running, AtomicLong sent)
            throws InterruptedException {
        try (AgentRuntime rt = AgentRuntime.builder().platformName(platform).network(new SocketNetwork(1 << 20, false))
                .stack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(key).identities(IdentityStore.ephemeral()).build())
                .build().start()) {
            SplittableRandom r = new SplittableRandom(23);
            java.util.ArrayDeque<AID> live = new java.util.ArrayDeque<>();
            while (running.get()) {
                // A few dozen at a time, each gone again a moment later: the attacker's memory stays flat.
                java.util.concurrent.CountDownLatch batch = new java.util.concurrent.CountDownLatch(1);
                rt.execute(() -> {
                    for (int i = 0; i < 20; i++) {
                        AID to = targets.get(r.nextInt(targets.size()));
                        live.add(rt.startAgent("intruder" + Long.toHexString(r.nextLong()), new OneMessage(to)));
                        sent.incrementAndGet();
                    }
                    while (live.size() > 200) {
                        rt.crashAgent(live.poll());
                    }
                    batch.countDown();
                });
                batch.await();
                Thread.sleep(5); // the attacker's loop does the handshakes meanwhile
            }
        }
    }

    /** Sends one message and stays, so that its handshake completes. */
    static final class OneMessage extends Agent {
        private final AID to;

        OneMessage(AID to) {
            this.to = to;
        }

        @Override
        protected void setup() {
            send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("let me in"));
        }
    }

    private static void tcp(List<InetSocketAddress> at, AtomicBoolean running, AtomicLong sent) throws InterruptedException {
        List<Socket> open = new ArrayList<>();
        byte[] head = preamble();
        while (running.get()) {
            for (InetSocketAddress a : at) {
                for (int i = 0; i < 20 && running.get(); i++) {
                    try {
                        Socket s = new Socket();
                        s.connect(a, 1_000);
                        OutputStream o = s.getOutputStream();
                        o.write(head);
                        o.flush();
                        open.add(s);
                        sent.incrementAndGet();
                    } catch (IOException e) {
                        // refused or closed by the agent: open another
                    }
                }
            }
            // Keep at most a few hundred of ours open; the agents close the rest.
            while (open.size() > 400) {
                try {
                    open.remove(0).close();
                } catch (IOException ignored) {
                    // gone already
                }
            }
            Thread.sleep(20);
        }
        for (Socket s : open) {
            try {
                s.close();
            } catch (IOException ignored) {
                // gone already
            }
        }
    }

    /** A stream preamble in an address of nobody's, then a frame announced at 1 MiB and 10 bytes of it. */
    private static byte[] preamble() {
        byte[] who = "tcp://127.0.0.9:9".getBytes(StandardCharsets.UTF_8);
        ByteBuffer b = ByteBuffer.allocate(6 + who.length + 4 + 10);
        b.put("CTCP".getBytes(StandardCharsets.US_ASCII)).putShort((short) who.length).put(who).putInt(1 << 20).put(new byte[10]);
        return b.array();
    }
}
