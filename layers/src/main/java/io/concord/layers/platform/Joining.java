package io.concord.layers.platform;

import io.concord.core.acl.Performative;

import java.util.function.Consumer;


/**
 * A join under way (dissertation fig. 5.7): INFORM-REF join to a container, sent again with a
 * growing wait until it CONFIRMs; after {@link PlatformConfig#joinAttempts()} the container is
 * taken for gone. A join outlives a role change (a container that yields joins the winner as a
 * member), so it is not a role's.
 */
final class Joining {
    private final PlatformContext ctx;
    private final PlatformState st;
    private final Consumer<AgentEntry> onFailed;
    private AgentEntry target;
    /** The term the target claimed. */
    private long targetTerm;
    /** The best container term heard of while seeking; a join asks for it. */
    long claimTerm = -1;
    private int failures;
    private long timer = -1;

    Joining(PlatformContext ctx, PlatformState st, Consumer<AgentEntry> onFailed) {
        this.ctx = ctx;
        this.st = st;
        this.onFailed = onFailed;
    }

    /** The container this agent is joining, or {@code null}. */
    AgentEntry target() {
        return target;
    }

    /** The term the container being joined claimed. */
    long targetTerm() {
        return targetTerm;
    }

    boolean to(String name) {
        return target != null && target.name().equals(name);
    }

    void start(AgentEntry container, long term) {
        target = container;
        targetTerm = term;
        claimTerm = Math.max(claimTerm, term);
        failures = 0;
        send();
    }

    /** The join is over (confirmed, or overtaken). */
    void stop() {
        target = null;
        timer = ctx.cancel(timer);
    }

    private void send() {
        timer = ctx.cancel(timer);
        ctx.send(Performative.INFORM_REF, Protocol.P_LAL, target.aid(), new PlatformMessage.Join(claimTerm, st.selfEntry));
        // Backing off: the first join to a container may wait for a signed handshake on a cold JVM.
        timer = ctx.after(ctx.config().joinRetryMs() << Math.min(failures, 4), this::onTimeout);
    }

    private void onTimeout() {
        timer = -1;
        if (target == null) {
            return;
        }
        if (++failures < ctx.config().joinAttempts()) {
            send();
            return;
        }
        ctx.trace("join-failed", target.name() + " did not confirm " + failures + " joins");
        AgentEntry failed = target;
        target = null;
        onFailed.accept(failed);
    }

}
