package jade.content.onto.basic;

import jade.content.Predicate;

/** SL's {@code false}. */
public class FalseProposition implements Predicate {
    private static final long serialVersionUID = 1L;
}
