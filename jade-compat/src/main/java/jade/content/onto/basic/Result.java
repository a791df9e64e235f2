package jade.content.onto.basic;

import jade.content.Concept;
import jade.content.Predicate;

/** The basic ontology's {@code (result act value)}: what an action gave. */
public class Result implements Predicate {
    private static final long serialVersionUID = 1L;
    private Concept action;
    private Object value;

    /** An empty proposition, for the ontology to fill. */
    public Result() {
    }

    /** That action gave that value (a term, or a {@code jade.util.leap.List} of terms). */
    public Result(Concept action, Object value) {
        this.action = action;
        this.value = value;
    }

    /** The action. */
    public Concept getAction() {
        return action;
    }

    /** Sets the action. */
    public void setAction(Concept action) {
        this.action = action;
    }

    /** The value. */
    public Object getValue() {
        return value;
    }

    /** Sets the value. */
    public void setValue(Object value) {
        this.value = value;
    }

    /** The value as a list (JADE's older accessor): the value itself when it is one. */
    public jade.util.leap.List getItems() {
        if (value instanceof jade.util.leap.List l) {
            return l;
        }
        jade.util.leap.List l = new jade.util.leap.ArrayList();
        if (value != null) {
            l.add(value);
        }
        return l;
    }

    /** Sets the value to that list. */
    public void setItems(jade.util.leap.List items) {
        this.value = items;
    }
}
