package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.SendRejectedException;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeoutException;

/**
 * Requests of the Java API ({@code PlatformServices}, above this package) to this platform's DF
 * or AMS: held until the agent knows its container, sent again on timeout (every request is
 * idempotent), and completed with the reply.
 */
final class ServiceRequests {
    private static final int ATTEMPTS = 4;

    private static final class Request {
        final boolean df;
        final Performative act;
        final String content;
        final String replyWith;
        final CompletableFuture<AclMessage> future = new CompletableFuture<>();
        int attempts;
        long timer = -1;

        Request(boolean df, Performative act, String content, String replyWith) {
            this.df = df;
            this.act = act;
            this.content = content;
            this.replyWith = replyWith;
        }
    }

    private final PlatformContext ctx;
    private final Roles roles;
    private final List<Request> waitingForContainer = new ArrayList<>();
    private final Map<String, Request> open = new HashMap<>();
    private long counter;

    ServiceRequests(PlatformContext ctx, Roles roles) {
        this.ctx = ctx;
        this.roles = roles;
    }

    private boolean containerKnown() {
        return roles.kind() != Role.SEEKING && roles.st.container != null;
    }

    CompletableFuture<AclMessage> request(boolean df, Performative p, String content) {
        Request r = new Request(df, p, content, ctx.self() + "-p" + (++counter));
        if (roles.kind() == Role.STOPPED) {
            r.future.completeExceptionally(new IllegalStateException("the agent has stopped"));
            return r.future;
        }
        open.put(r.replyWith, r);
        if (containerKnown()) {
            send(r);
        } else {
            waitingForContainer.add(r);
        }
        return r.future;
    }

    /** The content of a DF search for the agents whose services match the template. */
    static String searchContent(ServiceDescription template) {
        StringBuilder b = new StringBuilder();
        Lines.appendService(b, template);
        return Lines.content("search", Lines.params("template", b.toString()), List.of());
    }

    /** The entries of the DF's answer to a search; its refusal, as an exception. */
    static List<AgentEntry> entries(AclMessage reply) {
        if (reply.getPerformative() != Performative.INFORM) {
            throw new IllegalStateException("the DF answered " + reply.getPerformative().wireName() + ": " + reply.getContent());
        }
        return Lines.parse(reply.getContent()).entries();
    }

    private void send(Request r) {
        r.attempts++;
        AclMessage m = ctx.message(r.act, Protocol.P_SERVICES, AID.local(r.df ? "df" : "ams", ctx.platform()),
                r.content);
        m.setReplyWith(r.replyWith);
        PlatformState st = roles.st;
        long wait = Math.max(500, 2 * Math.max(st.timeoutMs, ctx.config().timeoutMs(st.lists.lal.size())));
        r.timer = ctx.after(wait, () -> {
            r.timer = -1;
            if (r.future.isDone()) {
                return;
            }
            if (r.attempts >= ATTEMPTS) {
                open.remove(r.replyWith);
                r.future.completeExceptionally(new TimeoutException("the " + (r.df ? "DF" : "AMS") + " did not answer "
                        + r.attempts + " requests; is a container elected?"));
            } else if (containerKnown()) {
                send(r);
            } else {
                waitingForContainer.add(r);
            }
        });
        try {
            ctx.sendOrThrow(m);
        } catch (SendRejectedException e) {
            open.remove(r.replyWith);
            r.timer = ctx.cancel(r.timer);
            r.future.completeExceptionally(e);
        }
    }

    /** True if the message answered one of these requests (and completed it). */
    boolean answer(AclMessage reply) {
        String to = reply.getInReplyTo();
        Request r = to == null ? null : open.remove(to);
        if (r == null) {
            return false;
        }
        r.timer = ctx.cancel(r.timer);
        r.future.complete(reply);
        return true;
    }

    /** The agent knows its container now (or again): requests held for it go. */
    void release() {
        if (waitingForContainer.isEmpty() || !containerKnown()) {
            return;
        }
        List<Request> ready = new ArrayList<>(waitingForContainer);
        waitingForContainer.clear();
        for (Request r : ready) {
            if (!r.future.isDone()) {
                send(r);
            }
        }
    }

    /**
     * The agent stopped: what still waits for the DF or the AMS fails, saying so (a future left
     * open would never complete). A request sent from takeDown() went, but its answer cannot come.
     */
    void stop() {
        List<Request> left = new ArrayList<>(open.values());
        open.clear();
        waitingForContainer.clear();
        for (Request r : left) {
            r.timer = ctx.cancel(r.timer);
            r.future.completeExceptionally(new IllegalStateException("the agent stopped before the "
                    + (r.df ? "DF" : "AMS") + " answered (a request from takeDown() is sent, but no answer can reach a stopped agent)"));
        }
    }
}
