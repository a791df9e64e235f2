package jade.content.onto.basic;

import jade.content.Predicate;

/** The basic ontology's {@code (= left right)}. */
public class Equals implements Predicate {
    private static final long serialVersionUID = 1L;
    private Object left;
    private Object right;

    /** An empty proposition, for the ontology to fill. */
    public Equals() {
    }

    /** {@code (= left right)}. */
    public Equals(Object left, Object right) {
        this.left = left;
        this.right = right;
    }

    /** The left term. */
    public Object getLeft() {
        return left;
    }

    /** Sets the left term. */
    public void setLeft(Object left) {
        this.left = left;
    }

    /** The right term. */
    public Object getRight() {
        return right;
    }

    /** Sets the right term. */
    public void setRight(Object right) {
        this.right = right;
    }
}
