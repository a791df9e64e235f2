package io.concord.agents.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.TickerBehaviour;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * The asking side of the wheelchair agents' request conversations, whose answers are not all
 * INFORM: a plan comes as INFORM-REF, a door's consent as CONFIRM. Each question gets its own
 * conversation id; an AGREE is passed to an optional callback, the first other answer completes
 * the future (REFUSE, FAILURE and NOT-UNDERSTOOD included: look at the performative), and no
 * answer within the timeout completes it with null. One instance per agent, added as a behaviour.
 *
 * <p>Not {@link io.concord.core.proto.Conversations#request}, which is FIPA-Request's initiator:
 * its future completes only on an INFORM (an INFORM-REF or a CONFIRM would be out of sequence and
 * never answer it), fails on REFUSE, FAILURE and NOT-UNDERSTOOD, keeps no AGREE for its caller (a
 * traffic agent's AGREE says whose reservation the chair waits behind), times out only by a
 * {@code :reply-by} carried on the message, and names the protocol and a reply-with of its own on
 * the wire. These questions are answered as docs/wheelchair-protocol.md says, time out on the
 * asker's own deadline with no {@code :reply-by} sent, and carry their conversation id as their
 * reply-with: what the other agents receive stays as it is.
 */
public final class Asks extends CyclicBehaviour {
    private record Pending(CompletableFuture<AclMessage> answer, Consumer<AclMessage> onAgree, long deadlineMs) {
    }

    private final Map<String, Pending> pending = new HashMap<>();
    private final String prefix;
    private long next;

    /** Asks for an agent; add it with {@code addBehaviour}. */
    public Asks(Agent agent) {
        super(agent);
        this.prefix = "ask-" + agent.getLocalName() + "-";
        agent.addBehaviour(new TickerBehaviour(agent, 100) {
            @Override
            protected void onTick() {
                expire();
            }
        });
    }

    /**
     * Sends {@code m} (with a conversation id of its own) and returns its answer.
     *
     * @param timeoutMs how long to wait for an answer other than AGREE
     * @param onAgree   told of an AGREE, or null
     */
    public CompletableFuture<AclMessage> ask(AclMessage m, long timeoutMs, Consumer<AclMessage> onAgree) {
        String id = prefix + (++next);
        m.setConversationId(id);
        m.setReplyWith(id);
        CompletableFuture<AclMessage> f = new CompletableFuture<>();
        pending.put(id, new Pending(f, onAgree, myAgent.currentTimeMillis() + timeoutMs));
        myAgent.send(m);
        return f;
    }

    /** Questions waiting for an answer. */
    public int pending() {
        return pending.size();
    }

    private final MessageTemplate template = m -> m.getConversationId() != null && pending.containsKey(m.getConversationId());

    @Override
    public void action() {
        AclMessage m = myAgent.receive(template);
        if (m == null) {
            block();
            return;
        }
        Pending p = pending.get(m.getConversationId());
        if (m.getPerformative() == Performative.AGREE) {
            if (p.onAgree() != null) {
                p.onAgree().accept(m);
            }
            return;
        }
        pending.remove(m.getConversationId());
        p.answer().complete(m);
    }

    private void expire() {
        long now = myAgent.currentTimeMillis();
        List<String> late = new ArrayList<>();
        for (Map.Entry<String, Pending> e : pending.entrySet()) {
            if (now >= e.getValue().deadlineMs()) {
                late.add(e.getKey());
            }
        }
        for (String id : late) {
            pending.remove(id).answer().complete(null);
        }
    }
}
