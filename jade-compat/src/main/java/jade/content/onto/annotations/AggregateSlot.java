package jade.content.onto.annotations;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** The facets of an aggregate slot (a list or a set property) of a bean, as in JADE. */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.METHOD, ElementType.FIELD})
public @interface AggregateSlot {
    /** The class of its elements; {@code Object} to take it from the property's generic type. */
    Class<?> type() default Object.class;

    /** Its fewest elements. */
    int cardMin() default 0;

    /** Its most elements; -1 for no limit. */
    int cardMax() default -1;
}
