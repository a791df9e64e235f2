package io.concord.core.content;

import jade.content.lang.sl.SLCodec;
import jade.content.lang.sl.SLOntology;
import jade.content.onto.Ontology;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * SL's operators, referential expressions and content lists, checked against JADE 4.3: each
 * vector is text JADE's SLCodec (over its SL ontology) reads and writes back unchanged, and
 * Concord's codec reads and writes back unchanged too.
 */
class JadeOperatorsTest {
    static final List<String> VECTORS = List.of(
            "(true)",
            "(false)",
            "(true (= 1 1) )",
            "((not true))",
            "((and true (not false)))",
            "((or true (implies true (equiv true false))))",
            "((forall ?x (exists ?y (= ?x ?y))))",
            "((exists ?x (and (= ?x 1) true)))",
            "((iota ?x (= ?x ?x)))",
            "((all (sequence ?x ?y) (= ?x ?y)))",
            "((any ?x (= ?x 1)))",
            "((= ?x (iota ?y (= ?y 1))))",
            "((= (set 1 2) (sequence \"a b\" x)))",
            "((B (agent-identifier :name a@P) (U (agent-identifier :name b@P) true)))",
            "((I (agent-identifier :name a@P) (PG (agent-identifier :name a@P) (= 1 2))))",
            "((result (action (agent-identifier :name a@P) (= 1 1)) true))");

    @Test
    void jadeAndConcordBothWriteBackEachVectorUnchanged() throws Exception {
        SLCodec jade = new SLCodec();
        Ontology ops = new Ontology("ops", SLOntology.getInstance());
        SlCodec concord = new SlCodec();
        for (String v : VECTORS) {
            assertEquals(v, jade.encode(ops, jade.decode(ops, v)), "JADE on " + v);
            assertEquals(v, concord.write(concord.read(v)), "Concord on " + v);
        }
    }

    @Test
    void jadeReadsTheTrueAndFalsePropositionsConcordWrites() throws Exception {
        ContentManager cm = new ContentManager().register(new SlCodec()).register(BasicOntology.INSTANCE);
        SLCodec jadeCodec = new SLCodec();
        for (Object p : List.of(new TrueProposition(), new FalseProposition())) {
            io.concord.core.acl.AclMessage msg = new io.concord.core.acl.AclMessage(io.concord.core.acl.Performative.INFORM);
            cm.fill(msg, p);
            Object jadeObject = jadeCodec.decode(jade.content.onto.BasicOntology.getInstance(), msg.getContent());
            Object back = jade.content.onto.BasicOntology.getInstance().toObject((jade.content.abs.AbsObject) jadeObject);
            assertEquals(p instanceof TrueProposition ? jade.content.onto.basic.TrueProposition.class
                    : jade.content.onto.basic.FalseProposition.class, back.getClass(), msg.getContent());
            assertEquals(p, cm.extract(msg));
        }
    }
}
