package io.concord.agents.control;

import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.List;

/** A patient transport as a control agent holds it, from the CFP to its end. */
final class Task {
    final String id;
    final int from;
    final int to;
    final double priority;
    final double unloadS;
    final AclMessage cfp;
    AclMessage accept;
    List<Integer> toPickup;
    List<Integer> toDropoff;
    double pathS;
    double costS;
    double estimateS;
    TaskView.State state = TaskView.State.EVALUATING;
    String reason;
    /** Why it is paused (the chair is held), or null. */
    String paused;
    int start;

    Task(String id, int from, int to, double priority, double unloadS, AclMessage cfp) {
        this.id = id;
        this.from = from;
        this.to = to;
        this.priority = priority;
        this.unloadS = unloadS;
        this.cfp = cfp;
    }

    /** The phase a progress report names, or null outside the four phases of a transport under way. */
    String phase() {
        return switch (state) {
            case TO_PICKUP -> "to-pickup";
            case LOADING -> "loading";
            case TO_DROPOFF -> "to-dropoff";
            case UNLOADING -> "unloading";
            default -> null;
        };
    }

    /** True from the moment the chair is at the patient until the patient is off: nobody else may take it. */
    boolean patientOnBoard() {
        return state.patientOnBoard();
    }

    /**
     * A notice to whoever gave the task (paused, resumed, progress), in its status conversation,
     * outside the contract's; null if the task was not given (never accepted).
     */
    AclMessage notice(WheelchairMessage notice) {
        if (accept == null) {
            return null;
        }
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addReceiver(accept.getSender());
        m.setOntology(Services.ONTOLOGY);
        m.setLanguage(Services.LANGUAGE);
        m.setConversationId(cfp.getConversationId() + "/status");
        m.setContent(notice.encode());
        return m;
    }

    TaskView view() {
        return new TaskView(id, from, to, priority, unloadS, state, costS, pathS, paused != null ? "paused: " + paused : reason);
    }
}
