package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeoutException;

/**
 * An agent's own yellow-pages registration, kept by the agent: what it asked the DF for
 * ({@link #wanted}) is its state, not the container's. Whenever its copy of the lists shows its
 * entry with other services (it joined or re-joined a container that does not have them: a new
 * container after a failover, or one that dropped it in a flap and added it back), it sends them
 * again; a refusal ({@code not-registered}: its entry is not in the container's list yet) is
 * logged once and retried when the entry appears, an unanswered request after a while. So a
 * service is never lost while its agent lives. Loop thread only.
 */
final class Registrations {
    private static final Logger LOG = LoggerFactory.getLogger(Registrations.class);
    /** How long after an unanswered or failed request it tries again. */
    private static final long RETRY_MS = 1_000;

    private final PlatformContext ctx;
    private final PlatformState st;
    private final ServiceRequests requests;
    /** What the agent asked for, or null if it never registered. */
    private List<ServiceDescription> wanted;
    /** Callers waiting until the container holds {@link #wanted}. */
    private final List<CompletableFuture<Void>> waiting = new ArrayList<>();
    private boolean inFlight;
    private long retryTimer = -1;
    private boolean refusalLogged;
    private boolean stopped;
    private long resent;
    private long refused;

    Registrations(PlatformContext ctx, PlatformState st, ServiceRequests requests) {
        this.ctx = ctx;
        this.st = st;
        this.requests = requests;
    }

    /**
     * The agent asks for these services ({@code add}: added to those it wants; otherwise in their
     * place). The future completes once the DF has taken them.
     */
    CompletableFuture<Void> want(List<ServiceDescription> services, boolean add) {
        List<ServiceDescription> next = new ArrayList<>();
        if (add) {
            List<ServiceDescription> base = wanted;
            if (base == null) {
                AgentEntry mine = st.lists.lal.get(ctx.self());
                base = mine == null ? List.of() : mine.services();
            }
            next.addAll(base);
            for (ServiceDescription d : services) {
                if (!next.contains(d)) {
                    next.add(d);
                }
            }
        } else {
            next.addAll(services);
        }
        wanted = List.copyOf(next);
        CompletableFuture<Void> f = new CompletableFuture<>();
        if (stopped) {
            f.completeExceptionally(new IllegalStateException("the agent has stopped"));
            return f;
        }
        waiting.add(f);
        send();
        return f;
    }

    /** Times this agent sent its services again on its own (after a flap, a failover, a refusal). */
    long resent() {
        return resent;
    }

    /** Times the DF did not take them (not listed yet, no container, no answer). */
    long refused() {
        return refused;
    }

    /** The lists or the container changed: if the container's view of this agent differs from what it wants, it says so again. */
    void reconcile() {
        if (wanted == null || inFlight || stopped || st.container == null) {
            return;
        }
        AgentEntry mine = st.lists.lal.get(ctx.self());
        if (mine == null) {
            return; // not in the list yet: the container adds it on join, and the lists change again
        }
        if (mine.services().equals(wanted)) {
            if (!waiting.isEmpty()) {
                completeWaiting();
            }
            return;
        }
        resent++;
        send();
    }

    void stop() {
        stopped = true;
        retryTimer = ctx.cancel(retryTimer);
    }

    private void send() {
        if (inFlight) {
            return; // the answer to the request out will reconcile again
        }
        inFlight = true;
        List<ServiceDescription> sent = wanted;
        StringBuilder b = new StringBuilder();
        Lines.appendServices(b, sent);
        requests.request(true, Performative.REQUEST, Lines.content("modify", Lines.params("services", b.toString()), List.of()))
                .whenComplete((reply, error) -> answered(sent, reply, error));
    }

    private void answered(List<ServiceDescription> sent, AclMessage reply, Throwable error) {
        inFlight = false;
        if (stopped) {
            return;
        }
        if (error == null && reply.getPerformative() == Performative.INFORM) {
            refusalLogged = false;
            if (sent.equals(wanted)) {
                completeWaiting();
            } else {
                send(); // asked for more meanwhile
            }
            return;
        }
        refused++;
        String why = error != null ? error.getMessage() : reply.getPerformative().wireName() + " " + reply.getContent();
        if (!refusalLogged) {
            refusalLogged = true;
            LOG.info("{}: the DF did not take its services ({}); it registers them again when its container lists it", ctx.self(), why);
        }
        boolean timeout = error instanceof TimeoutException
                || error != null && error.getCause() instanceof TimeoutException;
        if (error != null && !timeout) {
            // The agent stopped, or its message could not go: nothing to retry.
            failWaiting(error);
            return;
        }
        if (timeout) {
            // The callers hear that the DF did not answer; the registration itself is kept and sent
            // again when a container is there.
            failWaiting(error);
        }
        // A refusal (not in the container's list yet, or no container): the next change of the
        // lists tries again; so does a timer, in case nothing changes.
        retryTimer = ctx.cancel(retryTimer);
        retryTimer = ctx.after(RETRY_MS, () -> {
            retryTimer = -1;
            reconcile();
        });
    }

    private void completeWaiting() {
        List<CompletableFuture<Void>> done = new ArrayList<>(waiting);
        waiting.clear();
        for (CompletableFuture<Void> f : done) {
            f.complete(null);
        }
    }

    private void failWaiting(Throwable e) {
        List<CompletableFuture<Void>> done = new ArrayList<>(waiting);
        waiting.clear();
        for (CompletableFuture<Void> f : done) {
            f.completeExceptionally(e);
        }
    }
}
