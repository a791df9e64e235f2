package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.codec.AclParseException;
import io.concord.core.codec.StringAclCodec;
import io.concord.core.net.Channels;
import io.concord.core.acl.MtsFailure;

import io.concord.layers.authority.Policy;

import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The way to foreign platforms (the JADE bridge): the container serves the gateway; a member's
 * message to a foreign agent goes to its container wrapped in a {@code relay-out}, and a foreign
 * agent's message for a member comes from the container in a {@code relay-in}. The frames stay the
 * container's and the member's own, so identification holds on each hop.
 */
final class GatewayRelay implements PlatformMessage.Handler {
    private final PlatformContext ctx;
    private final PlatformState st;
    private final Gateway gateway;
    private final Policy policy;
    private final Supplier<Role> role;
    private final Consumer<AclMessage> toAgent;
    private final Consumer<Runnable> onLoop;
    private boolean started;

    GatewayRelay(PlatformContext ctx, PlatformState st, Gateway gateway, Policy policy, Supplier<Role> role,
                 Consumer<AclMessage> toAgent, Consumer<Runnable> onLoop) {
        this.policy = policy;
        this.ctx = ctx;
        this.st = st;
        this.gateway = gateway;
        this.role = role;
        this.toAgent = toAgent;
        this.onLoop = onLoop;
    }

    boolean present() {
        return gateway != null;
    }

    /** True if the gateway reaches that foreign receiver (then the container is its route). */
    boolean reaches(AID receiver) {
        return gateway != null && gateway.reaches(receiver);
    }

    /** This agent's message for a foreign receiver, wrapped for its container (the node {@code via}). */
    AclMessage wrap(AclMessage message, AID receiver, AID via) {
        return ctx.message(Performative.INFORM, Protocol.P_SERVICES, via, new PlatformMessage.RelayOut(receiver.name(),
                String.join(",", receiver.addresses()), StringAclCodec.INSTANCE.encodeToString(message)).encode());
    }

    private static AclMessage inner(String acl) {
        try {
            return StringAclCodec.INSTANCE.decode(acl);
        } catch (AclParseException e) {
            throw new IllegalArgumentException("a relayed message that does not parse: " + e.getMessage());
        }
    }

    /** From the container: a foreign agent's message for this agent. */
    @Override
    public void onRelayIn(PlatformMessage.RelayIn r, AclMessage wrapper) {
        AclMessage inner = inner(r.acl());
        if (st.container == null || !st.container.name().equals(wrapper.getSender().name())) {
            throw new IllegalArgumentException("a foreign message relayed by " + wrapper.getSender().name()
                    + ", which is not this agent's container");
        }
        toAgent.accept(inner);
    }

    /** From a member: a message for the container's gateway to carry out. */
    @Override
    public void onRelayOut(PlatformMessage.RelayOut r, AclMessage wrapper) {
        AclMessage inner = inner(r.acl());
        // A member relays its own messages only: the wrapper's sender is authenticated, the inner
        // message's is whatever the member wrote.
        if (inner.getSender() == null || !inner.getSender().name().equalsIgnoreCase(wrapper.getSender().name())) {
            ctx.drop("masquerade", wrapper.getSender().name() + " relayed a message in the name of "
                    + (inner.getSender() == null ? "nobody" : inner.getSender().name()) + " to " + r.receiver());
            return;
        }
        String addrs = r.addresses();
        AID receiver = new AID(r.receiver(), addrs.isEmpty() ? new String[0] : addrs.split(","));
        boolean container = role.get() == Role.CONTAINER;
        if (container && !started) {
            startGateway();
        }
        if (!container || !started) {
            // Nothing can carry it now: the sender hears so at once, and its protocol ends.
            ctx.drop("no-gateway", "a message for " + r.receiver() + " reached an agent that serves no gateway");
            if (inner.getSender() != null && inner.getPerformative() != Performative.FAILURE) {
                context.deliver(MtsFailure.of(ctx.platform(), inner, receiver,
                        "Foreign agent unreachable: the platform's gateway is not serving (its container is changing)"),
                        inner.getSender());
            }
            return;
        }
        gateway.sendOut(inner, receiver);
    }

    void startGateway() {
        if (gateway == null || started) {
            return;
        }
        started = true;
        try {
            gateway.start(context);
            ctx.trace("gateway", "started at " + gateway.addresses());
        } catch (RuntimeException e) {
            started = false;
            ctx.drop("gateway-failed", "the gateway did not start: " + e.getMessage());
        }
    }

    void stopGateway() {
        if (gateway != null && started) {
            started = false;
            try {
                gateway.stop();
            } catch (RuntimeException e) {
                ctx.drop("gateway-failed", "the gateway did not stop cleanly: " + e.getMessage());
            }
        }
    }

    /** What the gateway may do on this platform: deliver to its agents, and read the lists. */
    private final GatewayContext context = new GatewayContext() {
        @Override
        public String platformName() {
            return ctx.platform();
        }

        @Override
        public void execute(Runnable task) {
            onLoop.accept(task);
        }

        @Override
        public Channels channels() {
            return ctx.channels();
        }

        @Override
        public void after(long ms, Runnable task) {
            ctx.after(ms, task);
        }

        @Override
        public String refuses(AclMessage message, AID receiver) {
            if (Policy.principalOf(message, ctx.platform()) == Policy.Principal.MEMBER) {
                return null;   // the gateway's own answers for a member (a FAILURE from the AMS)
            }
            Policy.Decision d = policy.decide(Policy.Principal.FOREIGN, Policy.serviceOf(message));
            return d.allowed() ? null : d.reason();
        }

        @Override
        public boolean deliver(AclMessage message, AID receiver) {
            String refused = refuses(message, receiver);
            if (refused != null) {
                // The gateway should have asked first; whatever it does, the policy holds here.
                ctx.drop("not-authorized", (message.getSender() == null ? "a message with no sender" : message.getSender().name())
                        + " to " + receiver.name() + ": " + refused);
                return false;
            }
            String name = receiver.name();
            if (name.equalsIgnoreCase(ctx.self())) {
                toAgent.accept(message);
                return true;
            }
            AgentEntry e = st.lists.findIgnoringCase(name);
            if (e == null) {
                return false;
            }
            ctx.send(Performative.INFORM, Protocol.P_SERVICES, e.aid(),
                    new PlatformMessage.RelayIn(e.name(), StringAclCodec.INSTANCE.encodeToString(message)));
            return true;
        }

        @Override
        public List<AgentEntry> search(List<ServiceDescription> templates) {
            return st.lists.search(templates);
        }

        @Override
        public List<AgentEntry> agents() {
            return st.lists.all();
        }
    };
}
