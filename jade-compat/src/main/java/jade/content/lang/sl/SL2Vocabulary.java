package jade.content.lang.sl;

/** The symbols FIPA-SL2 adds: quantifiers, implication, modal operators, referential expressions. */
public interface SL2Vocabulary extends SL1Vocabulary {
    /** SL: {@code IOTA}. */
    String IOTA = "iota";
    /** SL: {@code ANY}. */
    String ANY = "any";
    /** SL: {@code ALL}. */
    String ALL = "all";
    /** SL: {@code IMPLIES}. */
    String IMPLIES = "implies";
    /** SL: {@code IMPLIES_LEFT}. */
    String IMPLIES_LEFT = "left";
    /** SL: {@code IMPLIES_RIGHT}. */
    String IMPLIES_RIGHT = "right";
    /** SL: {@code EQUIV}. */
    String EQUIV = "equiv";
    /** SL: {@code EQUIV_LEFT}. */
    String EQUIV_LEFT = "left";
    /** SL: {@code EQUIV_RIGHT}. */
    String EQUIV_RIGHT = "right";
    /** SL: {@code EXISTS}. */
    String EXISTS = "exists";
    /** SL: {@code EXISTS_WHAT}. */
    String EXISTS_WHAT = "what";
    /** SL: {@code EXISTS_CONDITION}. */
    String EXISTS_CONDITION = "condition";
    /** SL: {@code FORALL}. */
    String FORALL = "forall";
    /** SL: {@code FORALL_WHAT}. */
    String FORALL_WHAT = "what";
    /** SL: {@code FORALL_CONDITION}. */
    String FORALL_CONDITION = "condition";
    /** SL: {@code BELIEF}. */
    String BELIEF = "B";
    /** SL: {@code BELIEF_AGENT}. */
    String BELIEF_AGENT = "agent";
    /** SL: {@code BELIEF_CONDITION}. */
    String BELIEF_CONDITION = "condition";
    /** SL: {@code UNCERTAINTY}. */
    String UNCERTAINTY = "U";
    /** SL: {@code UNCERTAINTY_AGENT}. */
    String UNCERTAINTY_AGENT = "agent";
    /** SL: {@code UNCERTAINTY_CONDITION}. */
    String UNCERTAINTY_CONDITION = "condition";
    /** SL: {@code PERSISTENT_GOAL}. */
    String PERSISTENT_GOAL = "PG";
    /** SL: {@code PERSISTENT_GOAL_AGENT}. */
    String PERSISTENT_GOAL_AGENT = "agent";
    /** SL: {@code PERSISTENT_GOAL_CONDITION}. */
    String PERSISTENT_GOAL_CONDITION = "condition";
    /** SL: {@code INTENTION}. */
    String INTENTION = "I";
    /** SL: {@code INTENTION_AGENT}. */
    String INTENTION_AGENT = "agent";
    /** SL: {@code INTENTION_CONDITION}. */
    String INTENTION_CONDITION = "condition";
    /** SL: {@code FEASIBLE}. */
    String FEASIBLE = "feasible";
    /** SL: {@code FEASIBLE_ACTION}. */
    String FEASIBLE_ACTION = "action";
    /** SL: {@code FEASIBLE_CONDITION}. */
    String FEASIBLE_CONDITION = "condition";
    /** SL: {@code ACTION_SEQUENCE}. */
    String ACTION_SEQUENCE = ";";
    /** SL: {@code ACTION_SEQUENCE_FIRST}. */
    String ACTION_SEQUENCE_FIRST = "first";
    /** SL: {@code ACTION_SEQUENCE_SECOND}. */
    String ACTION_SEQUENCE_SECOND = "second";
    /** SL: {@code ACTION_ALTERNATIVE}. */
    String ACTION_ALTERNATIVE = "|";
    /** SL: {@code ACTION_ALTERNATIVE_FIRST}. */
    String ACTION_ALTERNATIVE_FIRST = "first";
    /** SL: {@code ACTION_ALTERNATIVE_SECOND}. */
    String ACTION_ALTERNATIVE_SECOND = "second";
}
