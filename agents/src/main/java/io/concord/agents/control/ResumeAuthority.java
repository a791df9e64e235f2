package io.concord.agents.control;

import io.concord.core.acl.AclMessage;
import io.concord.layers.authority.Operators;
import io.concord.layers.authority.Policy;
import io.concord.layers.authority.SignedOrder;

import java.util.Map;
import java.util.TreeMap;
import java.util.function.LongSupplier;

/**
 * Who may resume a chair held for an operator: the {@link Policy} says only an operator may
 * ({@link Policy.Service#CHAIR_RESUME}), and an operator is whoever signed the order with a key the
 * ward configured ({@link Operators}); the platform key, which any member holds, is not enough.
 * Every refusal is counted by its kind. On the agent's loop.
 */
final class ResumeAuthority {
    /** What a check found: who the operator is, or why the resume is refused. */
    record Verdict(String operator, String refusal) {
        boolean allowed() {
            return refusal == null;
        }
    }

    private volatile Operators operators = Operators.none();
    private Policy policy = Policy.defaults();
    private final LongSupplier epochMs;
    private final Map<String, Long> refusals = new TreeMap<>();

    ResumeAuthority(LongSupplier epochMs) {
        this.epochMs = epochMs;
    }

    void operators(Operators ops) {
        this.operators = ops;
    }

    void policy(Policy p) {
        this.policy = p;
    }

    /** Whether the authority checks are on (off only in a test's agent built without them). */
    boolean checks() {
        return policy.checks();
    }

    /** Refusals so far by kind ({@code foreign}, {@code unsigned}, {@code bad-order}). */
    Map<String, Long> refusals() {
        return new TreeMap<>(refusals);
    }

    /**
     * A {@code resume-request} from an agent: a member carrying an operator's signed order for this
     * chair. {@code platform}: this agent's platform, to tell members from agents of other platforms.
     */
    Verdict ofMessage(AclMessage m, String order, String chair, String platform) {
        if (!policy.checks()) {
            return new Verdict(m.getSender().localName(), null);   // a test's stack without the AUTHORITY defence
        }
        if (Policy.principalOf(m, platform) != Policy.Principal.MEMBER) {
            return refused("foreign", policy.decide(Policy.Principal.FOREIGN, Policy.Service.CHAIR_RESUME).reason());
        }
        if (order == null || order.isBlank()) {
            return refused("unsigned", m.getSender().localName() + " holds the platform key but no operator's order: only an operator may "
                    + "resume " + chair + " (a resume-request carries :order, signed with an operator key the ward configured)");
        }
        return ofOrder(order, chair);
    }

    /** An order given in this process (the console's, signed with the operator key it was started with). */
    Verdict ofOrder(String order, String chair) {
        if (!policy.checks()) {
            return new Verdict("an operator", null);
        }
        SignedOrder o;
        try {
            o = SignedOrder.parse(order);
        } catch (IllegalArgumentException e) {
            return refused("bad-order", e.getMessage());
        }
        String why = operators.verify(o, "resume", chair, epochMs.getAsLong());
        if (why != null) {
            return refused("bad-order", why);
        }
        if (!policy.allows(Policy.Principal.OPERATOR, Policy.Service.CHAIR_RESUME)) {
            return refused("policy", policy.decide(Policy.Principal.OPERATOR, Policy.Service.CHAIR_RESUME).reason());
        }
        return new Verdict(o.operator(), null);
    }

    private Verdict refused(String kind, String why) {
        refusals.merge(kind, 1L, Long::sum);
        return new Verdict(null, why);
    }
}
