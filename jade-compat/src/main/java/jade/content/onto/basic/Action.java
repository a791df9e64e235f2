package jade.content.onto.basic;

import jade.content.AgentAction;
import jade.content.Concept;
import jade.core.AID;

/** The basic ontology's {@code (action actor act)}: an agent action and who is to do it. */
public class Action implements AgentAction {
    private static final long serialVersionUID = 1L;
    private AID actor;
    private Concept action;

    /** An empty action, for the ontology to fill. */
    public Action() {
    }

    /** That actor doing that action. */
    public Action(AID actor, Concept action) {
        this.actor = actor;
        this.action = action;
    }

    /** Who is to do it. */
    public AID getActor() {
        return actor;
    }

    /** Sets who is to do it. */
    public void setActor(AID actor) {
        this.actor = actor;
    }

    /** What is to be done. */
    public Concept getAction() {
        return action;
    }

    /** Sets what is to be done. */
    public void setAction(Concept action) {
        this.action = action;
    }
}
