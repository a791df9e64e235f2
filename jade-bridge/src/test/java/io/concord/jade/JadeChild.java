package io.concord.jade;

import jade.core.AID;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.wrapper.ContainerController;

/**
 * A JADE 4.3 platform in a JVM of its own: a main container with the HTTP MTP (and the parser
 * fix), an echo agent, and an agent that REQUESTs a Concord agent and prints the answer. Arguments:
 * platform id, HTTP port, the Concord agent's name, its ACC URL. Prints {@code READY}, then
 * {@code ANSWER <performative> <content>}.
 */
public final class JadeChild {
    /** REQUESTs the Concord agent given in its arguments and prints the answer. */
    public static final class Asker extends jade.core.Agent {
        @Override
        protected void setup() {
            Object[] a = getArguments();
            addBehaviour(new OneShotBehaviour(this) {
                @Override
                public void action() {
                    AID to = new AID((String) a[0], AID.ISGUID);
                    to.addAddresses((String) a[1]);
                    for (int i = 0; i < 50; i++) {
                        ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
                        req.addReceiver(to);
                        req.setContent("from-jade-process");
                        req.setConversationId("p" + i);
                        myAgent.send(req);
                        ACLMessage r = myAgent.blockingReceive(MessageTemplate.MatchConversationId("p" + i), 2_000);
                        if (r != null && r.getPerformative() == ACLMessage.INFORM) {
                            System.out.println("ANSWER INFORM " + r.getContent());
                            return;
                        }
                        myAgent.doWait(200);
                    }
                    System.out.println("ANSWER NONE");
                }
            });
        }
    }

    public static void main(String[] args) throws Exception {
        jade.core.Runtime rt = jade.core.Runtime.instance();
        jade.core.Profile p = new jade.core.ProfileImpl();
        p.setParameter(jade.core.Profile.GUI, "false");
        p.setParameter(jade.core.Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(jade.core.Profile.LOCAL_PORT, Integer.toString(JadeBridgeTest.freePort()));
        p.setParameter(jade.core.Profile.PLATFORM_ID, args[0]);
        p.setParameter(jade.core.Profile.DETECT_MAIN, "false");
        p.setParameter(jade.core.Profile.MTPS, "jade.mtp.http.MessageTransportProtocol(http://127.0.0.1:" + args[1] + "/acc)");
        p.setParameter("jade_mtp_http_parser", JadeSaxParser.class.getName());
        ContainerController main = rt.createMainContainer(p);
        main.createNewAgent("jecho", JadeBridgeTest.JadeEcho.class.getName(), new Object[0]).start();
        System.out.println("READY");
        main.createNewAgent("asker", Asker.class.getName(), new Object[]{args[2], args[3]}).start();
        // Runs until the parent closes our standard input.
        while (System.in.read() >= 0) {
            // nothing to read
        }
        System.exit(0);
    }
}
