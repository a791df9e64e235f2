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

    /** The white pages: every agent of the host, or the one of that name. */
    record Agents(String name) implements Action {
    }

    private final PlatformContext ctx;
    private final Roles roles;

    Directory(PlatformContext ctx, Roles roles) {
        this.ctx = ctx;
        this.roles = roles;
    }

    void serve(AclMessage m) {
        Performative act = m.getPerformative();
        if (act != Performative.REQUEST && act != Performative.QUERY_REF) {
            if (act == Performative.CFP || act == Performative.QUERY_IF || act == Performative.SUBSCRIBE
                    || act == Performative.PROPOSE) {
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
