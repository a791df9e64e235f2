package io.concord.core.content;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * How a record component (or field) of a {@link BeanOntology} element maps to a slot, as JADE's
 * {@code @Slot} and {@code @AggregateSlot} do: by default the slot has the component's name, is
 * optional (mandatory for a Java primitive type such as {@code int}), and an aggregate has any
 * number of elements.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.RECORD_COMPONENT, ElementType.FIELD, ElementType.PARAMETER, ElementType.METHOD})
public @interface Slot {
    /** The slot's name; empty for the component's name. */
    String name() default "";

    /** Whether the slot must have a value (for an aggregate: at least {@link #cardMin()} elements). */
    boolean mandatory() default false;

    /** An aggregate's fewest elements. */
    int cardMin() default 0;

    /** An aggregate's most elements; -1 for no limit. */
    int cardMax() default -1;

    /**
     * The slot's place (0, 1, ...) when its element is written by position, as the FIPA
     * agent-management actions are ({@code (search description constraints)}); -1 for none. When
     * one component of an element has a position, all must, the slots keep that order instead of
     * the alphabetical one, and the element is written and read by position.
     */
    int position() default -1;
}
