package jade.content.onto.basic;

import jade.content.Concept;
import jade.content.Predicate;

/** The basic ontology's {@code (done act)}: the action has been carried out. */
public class Done implements Predicate {
    private static final long serialVersionUID = 1L;
    private Concept action;
    private Predicate condition;

    /** An empty proposition, for the ontology to fill. */
    public Done() {
    }

    /** That action is done. */
    public Done(Concept action) {
        this.action = action;
    }

    /** The action done. */
    public Concept getAction() {
        return action;
    }

    /** Sets the action done. */
    public void setAction(Concept action) {
        this.action = action;
    }

    /** JADE's optional condition; not written here (see README): SL's {@code done} is written with one argument. */
    public Predicate getCondition() {
        return condition;
    }

    /** Sets the condition (kept on the object, not written). */
    public void setCondition(Predicate condition) {
        this.condition = condition;
    }
}
