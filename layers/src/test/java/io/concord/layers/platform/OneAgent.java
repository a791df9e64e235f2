package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.internal.CoLocated;
import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.net.internal.Neighbourhood;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;

import java.util.ArrayList;
import java.util.List;

/**
 * One agent's container layer alone on the layer harness, with a manual clock: the test plays
 * every other agent by hand, handing it platform messages and reading what it sends.
 */
final class OneAgent {
    static final String PLATFORM = "p";
    static final long EPOCH = ManualClock.DEFAULT_EPOCH_MS;

    /** A message the agent sent: to whom, where, and what. */
    record Out(Performative act, String to, Address at, PlatformMessage what, AclMessage raw) {
    }

    final ContainerLayer layer;
    final LayerHarness h;
    final AgentEntry self;
    /** The addresses of the agents taken to run in this agent's runtime (none unless a test adds them). */
    final java.util.Set<Address> coLocated = new java.util.HashSet<>();
    /** Of those, the container layers this agent may read in memory (none unless a test adds them). */
    final java.util.Map<Address, ContainerLayer> peers = new java.util.HashMap<>();

    /** An agent named {@code local} at port {@code port}, with other agents holding the ports given. */
    OneAgent(String local, int port, PlatformConfig config, int... neighbourPorts) {
        this(local, port, config, null, neighbourPorts);
    }

    /** ... serving a gateway when container ({@code null}: none). */
    OneAgent(String local, int port, PlatformConfig config, Gateway gateway, int... neighbourPorts) {
        this(local, port, config, null, gateway, neighbourPorts);
    }

    /** ... and in touch with the containers of other hosts ({@code network}; {@code null}: none). */
    OneAgent(String local, int port, PlatformConfig config, NetworkConfig network, Gateway gateway, int... neighbourPorts) {
        List<Address> around = new ArrayList<>();
        for (int p : neighbourPorts) {
            around.add(new Address("127.0.0.1", p));
        }
        layer = new ContainerLayer(config, network, gateway);
        h = LayerHarness.builder().name(local + "@" + PLATFORM).localAddress(new Address("127.0.0.1", port))
                .offer(Neighbourhood.class, new Neighbourhood() {
                    @Override
                    public List<Address> neighbours() {
                        return around;
                    }

                    @Override
                    public Endpoint openListener(int p) {
                        return null;
                    }

                    @Override
                    public List<String> broadcastAddresses() {
                        return List.of();
                    }
                })
                .offer(CoLocated.class, new CoLocated() {
                    @Override
                    public boolean here(Address address) {
                        return coLocated.contains(address);
                    }

                    @Override
                    public Runnable whenGone(Address address, Runnable callback) {
                        return () -> { };
                    }

                    @Override
                    public <T> T layer(Address address, Class<T> type) {
                        ContainerLayer l = coLocated.contains(address) ? peers.get(address) : null;
                        return type.isInstance(l) ? type.cast(l) : null;
                    }
                }).build(layer);
        self = layer.selfEntry();
    }

    OneAgent(String local, int port, int... neighbourPorts) {
        this(local, port, PlatformConfig.defaults(), neighbourPorts);
    }

    /** Another agent's entry: started {@code ageMs} before this one (negative: after). */
    static AgentEntry other(String local, int port, long ageMs) {
        return new AgentEntry(local + "@" + PLATFORM, "udp://127.0.0.1:" + port, EPOCH - ageMs, List.of());
    }

    /** Hands the agent a platform message from another agent, as its stack would. */
    void from(AgentEntry sender, Performative act, String protocol, PlatformMessage content) {
        h.receiveUp(Envelope.outgoing(message(sender, act, protocol, content), self.aid(), null));
    }

    /**
     * ... as a frame for any agent at this port would bring it: sealed with the platform key alone,
     * so whoever holds the key could have written it in any name.
     */
    void fromAny(AgentEntry sender, Performative act, String protocol, PlatformMessage content) {
        Envelope env = Envelope.outgoing(message(sender, act, protocol, content), self.aid(), null);
        env.putHeader(io.concord.layers.frame.Frames.ENVELOPE_ANY, Boolean.TRUE);
        h.receiveUp(env);
    }

    private AclMessage message(AgentEntry sender, Performative act, String protocol, PlatformMessage content) {
        AclMessage m = new AclMessage(act);
        m.setSender(sender.aid());
        m.addReceiver(self.aid());
        m.setOntology(Protocol.ONTOLOGY);
        m.setLanguage(Protocol.LANGUAGE);
        m.setProtocol(protocol);
        m.setContent(content.encode());
        return m;
    }

    /** Everything the agent sent since the last call, decoded. */
    List<Out> sent() {
        List<Out> out = new ArrayList<>();
        for (Envelope e = h.pollDown(); e != null; e = h.pollDown()) {
            AclMessage m = e.message();
            out.add(new Out(m.getPerformative(), e.receiver().name(), e.destination(), PlatformMessage.decode(m), m));
        }
        return out;
    }

    /** What it sent of one kind. */
    <T extends PlatformMessage> List<T> sent(Class<T> type) {
        List<T> out = new ArrayList<>();
        for (Out o : sent()) {
            if (type.isInstance(o.what())) {
                out.add(type.cast(o.what()));
            }
        }
        return out;
    }

    Role role() {
        return layer.role();
    }

    void advance(long ms) {
        // Step by step, so that timers set by timers run on time too.
        for (long i = 0; i < ms; i++) {
            h.advanceMs(1);
        }
    }
}
