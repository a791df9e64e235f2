package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.internal.CoLocated;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.layer.StackHost;
import io.concord.core.layer.Tracer;
import io.concord.core.net.Address;
import io.concord.core.net.Channels;
import io.concord.core.net.internal.Neighbourhood;
import io.concord.layers.frame.Frames;

import java.util.function.Predicate;
import java.util.random.RandomGenerator;

import static io.concord.layers.platform.Protocol.LANGUAGE;
import static io.concord.layers.platform.Protocol.ONTOLOGY;

/** The container layer's {@link PlatformContext}: its node's services, narrowed to what the platform uses. */
final class HostContext implements PlatformContext {
    private final StackHost host;
    private final PlatformConfig config;
    private final PlatformState st;
    private final String platform;
    private final String self;
    private final AID selfAid;
    private final LayerContext layer;
    private final Predicate<Envelope> place;

    /**
     * @param layer the container layer's place in the stack: its own messages go down from there
     * @param place gives a copy its destination (false if it has none, and was dropped)
     */
    HostContext(StackHost host, LayerContext layer, PlatformConfig config, PlatformState st, String platform, AID selfAid,
                Predicate<Envelope> place) {
        this.host = host;
        this.layer = layer;
        this.place = place;
        this.config = config;
        this.st = st;
        this.platform = platform;
        this.self = selfAid.name();
        this.selfAid = selfAid;
    }

    @Override
    public PlatformConfig config() {
        return config;
    }

    @Override
    public String platform() {
        return platform;
    }

    @Override
    public String self() {
        return self;
    }

    @Override
    public AgentEntry selfEntry() {
        return st.selfEntry;
    }

    @Override
    public AID selfAid() {
        return selfAid;
    }

    @Override
    public long nowNs() {
        return host.nowNs();
    }

    @Override
    public long epochMillis() {
        return host.clock().epochMillis();
    }

    @Override
    public long after(long ms, Runnable task) {
        return host.schedule(host.nowNs() + ms * 1_000_000L, task);
    }

    @Override
    public long cancel(long id) {
        if (id >= 0) {
            host.cancel(id);
        }
        return -1;
    }

    @Override
    public Boolean portHeld(AgentEntry e) {
        if (!st.portCheck) {
            return null;
        }
        Address at = e.transportAddress();
        if (at != null && at.equals(host.localAddress())) {
            return e.name().equals(self); // this agent holds that port now: whoever had it before is gone
        }
        String holder = at == null ? null : st.heardAt.get(at);
        if (holder != null && !holder.equals(e.name())) {
            return Boolean.FALSE; // another agent speaks from its port now: its process is gone
        }
        Neighbourhood around = host.capability(Neighbourhood.class);
        return around == null ? null : around.held(at);
    }

    @Override
    public CoLocated coLocated() {
        return host.capability(CoLocated.class);
    }

    @Override
    public Channels channels() {
        return host.capability(Channels.class);
    }

    @Override
    public RandomGenerator random() {
        return host.random();
    }

    @Override
    public void secretBytes(byte[] out) {
        host.secretBytes(out);
    }

    @Override
    public AclMessage message(Performative act, String protocol, AID to, String content) {
        AclMessage m = new AclMessage(act);
        m.setSender(selfAid);
        m.addReceiver(to);
        m.setOntology(ONTOLOGY);
        m.setLanguage(LANGUAGE);
        m.setProtocol(protocol);
        m.setContent(content);
        return m;
    }

    @Override
    public void send(Performative act, String protocol, AID to, PlatformMessage content) {
        sendQuietly(message(act, protocol, to, content.encode()));
    }

    @Override
    public AclMessage reply(AclMessage to, Performative act, PlatformMessage content) {
        AclMessage r = ContainerLayer.stamped(to, epochMillis()).createReply();
        r.setPerformative(act);
        r.setSender(selfAid);
        r.setOntology(ONTOLOGY);
        r.setLanguage(LANGUAGE);
        r.setContent(content.encode());
        return r;
    }

    @Override
    public void sendQuietly(AclMessage m) {
        try {
            sendOrThrow(m);
        } catch (SendRejectedException e) {
            host.drops().record(self, e.reason(), e.getMessage());
        } catch (RuntimeException e) {
            host.drops().record(self, "platform-send", e.toString());
        }
    }

    @Override
    public void sendOrThrow(AclMessage m) {
        Tracer t = host.tracer();
        for (AID r : m.getReceivers()) {
            if (t.enabled()) {
                t.trace(host.nowNs(), self, "send", Tracer.describe(m) + " to " + r.name());
            }
            Envelope env = Envelope.outgoing(m, r, null);
            if (place.test(env)) {
                layer.passDown(env);
            }
        }
    }

    @Override
    public AID anyAt(Address a) {
        return new AID(Frames.ANY_LOCAL_NAME + "@" + platform, a.toUri(host.transport()));
    }

    @Override
    public void trace(String event, String detail) {
        Tracer t = host.tracer();
        if (t.enabled()) {
            t.trace(host.nowNs(), self, "platform-" + event, detail);
        }
    }

    @Override
    public void drop(String reason, String detail) {
        host.drops().record(self, reason, detail);
    }
}
