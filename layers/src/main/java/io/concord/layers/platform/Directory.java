package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.ArrayList;
import java.util.List;

/**
 * The white and yellow pages as the container serves them: {@code ams@platform} and
 * {@code df@platform}. Every agent's services are in its LAL entry, so the pages survive a
 * failover. Requests are decoded into {@link Action}s; a request to an agent that is not the
 * container is answered FAILURE (not-container, naming the container if known).
 */
final class Directory {

    /** What may be asked of the DF and the AMS. */
    sealed interface Action {
        static Action decode(Lines.Content c) {
            return switch (c.command()) {
                case "register" -> new Register(Lines.parseServices(c.params().getOrDefault("services", "-")), false);
                case "modify" -> new Register(Lines.parseServices(c.params().getOrDefault("services", "-")), true);
                case "deregister" -> new Deregister();
                case "search" -> new Search(Lines.parseService(c.params().getOrDefault("template", "*")));
                case "agents" -> new Agents(c.params().get("name"));
                case "subscribe" -> new Subscribe(Lines.parseService(c.params().getOrDefault("template", "*")));
                default -> null;
            };
        }
    }

    /** Adds services to the sender's ({@code register}), or replaces them ({@code modify}). */
    record Register(List<ServiceDescription> services, boolean replace) implements Action {
    }

    record Deregister() implements Action {
    }

    record Search(ServiceDescription template) implements Action {
    }

    /** Tell the sender of the agents whose services match the template, now and on every change (FIPA subscribe). */
    record Subscribe(ServiceDescription template) implements Action {
    }

    /** The white pages: every agent of the host, or the one of that name. */
    record Agents(String name) implements Action {
    }

    private final PlatformContext ctx;
    private final Roles roles;
    private final DfSubscriptions subscriptions = new DfSubscriptions();

    Directory(PlatformContext ctx, Roles roles) {
        this.ctx = ctx;
        this.roles = roles;
    }

    void serve(AclMessage m) {
        Performative act = m.getPerformative();
        if (act == Performative.CANCEL) {
            // FIPA's subscribe protocol ends with a cancel in the subscription's conversation; nothing answers it.
            subscriptions.cancel(m.getSender().name(), m.getConversationId());
            return;
        }
        if (act != Performative.REQUEST && act != Performative.QUERY_REF && act != Performative.SUBSCRIBE) {
            if (act == Performative.CFP || act == Performative.QUERY_IF || act == Performative.PROPOSE) {
                ctx.sendQuietly(reply(m, Performative.NOT_UNDERSTOOD, "(unsupported-act " + act.wireName() + ")"));
            }
            return;
        }
        PlatformState st = roles.st;
        if (!(roles.current() instanceof ContainerRole container)) {
            ctx.sendQuietly(reply(m, Performative.FAILURE, "(not-container"
                    + (st.container == null ? "" : " " + Lines.escape(st.container.name())) + ")"));
            return;
        }
        Lines.Content c;
        Action a;
        try {
            c = Lines.parse(m.getContent());
            a = Action.decode(c);
        } catch (IllegalArgumentException e) {
            ctx.sendQuietly(reply(m, Performative.NOT_UNDERSTOOD, "(malformed \"" + e.getMessage().replace("\"", "'") + "\")"));
            return;
        }
        String from = m.getSender().name();
        AgentEntry entry = st.lists.lal.get(from);
        if ((act == Performative.SUBSCRIBE) != (a instanceof Subscribe)) {
            ctx.sendQuietly(reply(m, Performative.NOT_UNDERSTOOD, "(unsupported-act " + act.wireName() + " "
                    + Lines.escape(c.command()) + ")"));
            return;
        }
        if (a instanceof Subscribe s) {
            // As JADE's DF: no agree; the entries that match now at once, if any, then every change.
            List<AgentEntry> now = subscriptions.add(ContainerLayer.stamped(m, ctx.epochMillis()), s.template(),
                    t -> st.lists.search(List.of(t)));
            if (!now.isEmpty()) {
                ctx.sendQuietly(notification(m, now));
            }
            return;
        }
        if (a instanceof Register r) {
            if (entry == null) {
                ctx.sendQuietly(reply(m, Performative.REFUSE, "(not-registered " + Lines.escape(from) + ")"));
                return;
            }
            List<ServiceDescription> s = r.services();
            if (!r.replace() && !entry.services().isEmpty()) {
                List<ServiceDescription> merged = new ArrayList<>(entry.services());
                for (ServiceDescription d : s) {
                    if (!merged.contains(d)) {
                        merged.add(d);
                    }
                }
                s = merged;
            }
            container.servicesChanged(entry, s);
            ctx.sendQuietly(reply(m, Performative.INFORM, "done"));
        } else if (a instanceof Deregister) {
            if (entry != null) {
                container.servicesChanged(entry, List.of());
            }
            ctx.sendQuietly(reply(m, Performative.INFORM, "done"));
        } else if (a instanceof Search s) {
            List<AgentEntry> found = st.lists.search(List.of(s.template()));
            ctx.sendQuietly(reply(m, Performative.INFORM, Lines.content("result", Lines.params("count", found.size()), found)));
        } else if (a instanceof Agents g) {
            List<AgentEntry> found = new ArrayList<>();
            for (AgentEntry e : st.lists.lal.values()) {
                if (g.name() == null || e.name().equalsIgnoreCase(g.name())) {
                    found.add(e);
                }
            }
            ctx.sendQuietly(reply(m, Performative.INFORM, Lines.content("result",
                    Lines.params("count", found.size(), "container", ctx.self(), "term", st.term), found)));
        } else {
            ctx.sendQuietly(reply(m, Performative.NOT_UNDERSTOOD, "(unknown-action " + Lines.escape(c.command()) + ")"));
        }
    }

    /**
     * The container's list changed: each subscriber whose matches changed is told (called by the
     * layer after every change, while this agent is the container).
     */
    void listChanged() {
        if (subscriptions.size() == 0) {
            return;
        }
        PlatformState st = roles.st;
        subscriptions.changed(st.lists.lal::containsKey, t -> st.lists.search(List.of(t)),
                (request, changed) -> ctx.sendQuietly(notification(request, changed)));
    }

    /** The subscriptions held (for tests). */
    int subscriptions() {
        return subscriptions.size();
    }

    private AclMessage notification(AclMessage subscribe, List<AgentEntry> entries) {
        return reply(subscribe, Performative.INFORM, Lines.content("result", Lines.params("count", entries.size()), entries));
    }

    private AclMessage reply(AclMessage m, Performative p, String content) {
        AclMessage r = ContainerLayer.stamped(m, ctx.epochMillis()).createReply();
        r.setPerformative(p);
        // Sent as the container itself: the frame is authenticated as the container's, and the
        // receiver's identification check holds the sender's name to that.
        r.setSender(ctx.selfAid());
        r.setContent(content);
        r.setLanguage(Protocol.LANGUAGE);
        return r;
    }
}
