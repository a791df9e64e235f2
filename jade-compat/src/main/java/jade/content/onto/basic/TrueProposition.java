package jade.content.onto.basic;

import jade.content.Predicate;

/** SL's {@code true}. */
public class TrueProposition implements Predicate {
    private static final long serialVersionUID = 1L;
}
