import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREInitiator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Vector;

/** Requests a job of five responders; every handler records what it saw, printed sorted at the end. */
public class Initiator extends Agent {
    private final List<String> events = new ArrayList<>();

    @Override
    protected void setup() {
        ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
        for (String n : new String[] {"agreeing", "refusing", "direct", "failing", "puzzled"}) {
            req.addReceiver(new AID(n, AID.ISLOCALNAME));
        }
        req.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
        req.setContent("job");
        addBehaviour(new AchieveREInitiator(this, req) {
            private int allResponsesCalls;

            @Override
            protected void handleAgree(ACLMessage agree) {
                events.add("agree from " + agree.getSender().getLocalName());
            }

            @Override
            protected void handleRefuse(ACLMessage refuse) {
                events.add("refuse from " + refuse.getSender().getLocalName() + ": " + refuse.getContent());
            }

            @Override
            protected void handleNotUnderstood(ACLMessage nu) {
                events.add("not-understood from " + nu.getSender().getLocalName() + ": " + nu.getContent());
            }

            @Override
            protected void handleInform(ACLMessage inform) {
                events.add("inform from " + inform.getSender().getLocalName() + ": " + inform.getContent()
                        + " protocol " + inform.getProtocol());
            }

            @Override
            protected void handleFailure(ACLMessage failure) {
                events.add("failure from " + failure.getSender().getLocalName() + ": " + failure.getContent());
            }

            @Override
            protected void handleAllResponses(Vector responses) {
                allResponsesCalls++;
                events.add("all responses: " + senders(responses));
            }

            @Override
            protected void handleAllResultNotifications(Vector notifications) {
                events.add("all result notifications: " + senders(notifications));
                Collections.sort(events);
                for (String e : events) {
                    System.out.println(e);
                }
                System.out.println("handleAllResponses called " + allResponsesCalls + " time(s)");
                myAgent.doDelete();
            }
        });
    }

    private static String senders(Vector v) {
        List<String> l = new ArrayList<>();
        for (Object o : v) {
            ACLMessage m = (ACLMessage) o;
            l.add(ACLMessage.getPerformative(m.getPerformative()) + ":" + m.getSender().getLocalName());
        }
        Collections.sort(l);
        return l.toString();
    }

    @Override
    protected void takeDown() {
        System.out.flush();
        System.exit(0);
    }
}
